#pragma once
// What a long recording must not accumulate, read from /proc/self (Linux): resident memory, open
// file descriptors and threads. A soak samples them every second to tell a leak from a plateau.
// Beside resident memory, the bytes the program holds from the allocator: when resident memory
// steps up while these stay flat, the allocator kept freed pages, not the program its data. That
// is why a soak judges growth on the heap in use and only reports resident memory.
#include <cstdint>

namespace lmc::devices {

struct ProcessStats {
  double rss_mb = 0;          // resident set size, MiB
  double heap_in_use_mb = 0;  // allocated and not freed (glibc's mallinfo2, or ASan's count), MiB; 0 elsewhere
  int fds = 0;                // open file descriptors
  int threads = 0;
};

// Zeros where /proc is not there to read (the soak then cannot judge growth and says so).
ProcessStats read_process_stats();

}  // namespace lmc::devices
