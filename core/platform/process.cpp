#include "core/platform/process.h"

#ifdef _WIN32
#include <io.h>
#include <process.h>

#include <cstdio>
#else
#include <unistd.h>
#endif

namespace lmc::platform {

#ifdef _WIN32
int current_process_id() {
  return _getpid();
}
bool stderr_is_terminal() {
  return _isatty(_fileno(stderr)) != 0;
}
#else
int current_process_id() {
  return static_cast<int>(::getpid());
}
bool stderr_is_terminal() {
  return ::isatty(STDERR_FILENO) != 0;
}
#endif

}  // namespace lmc::platform
