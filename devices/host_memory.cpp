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

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  // A trial's largest buffers are a few MB; 256 MB keeps them all on the heap, and 1 GB of free
  // memory at the heap's top is never reached by a batch.
  ::mallopt(M_MMAP_THRESHOLD, 256 << 20);
  ::mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace lmc::devices
