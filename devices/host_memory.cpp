#include "devices/host_memory.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace lmc::devices {

void return_freed_memory() {
#if defined(__GLIBC__)
  ::malloc_trim(0);
#endif
}

}  // namespace lmc::devices
