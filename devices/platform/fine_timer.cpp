#include "devices/platform/fine_timer.h"

#ifdef _WIN32
#include <windows.h>
// After windows.h, which it needs.
#include <timeapi.h>
#endif

namespace lmc::devices {

#ifdef _WIN32
// 1 ms: the finest period Windows grants; it is reference counted, so every holder asks for it.
FineTimerResolution::FineTimerResolution() : raised_(timeBeginPeriod(1) == TIMERR_NOERROR) {}
FineTimerResolution::~FineTimerResolution() {
  if (raised_) timeEndPeriod(1);
}
#else
FineTimerResolution::FineTimerResolution() = default;
FineTimerResolution::~FineTimerResolution() = default;
#endif

}  // namespace lmc::devices
