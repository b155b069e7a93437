#pragma once
// What a long recording must not accumulate: resident memory, open file descriptors (handles on
// Windows) and threads, read from /proc/self on Linux (process_stats_linux.cpp) and from the
// process's counters on Windows (process_stats_windows.cpp). A soak samples them every second to tell a leak from a
// plateau. Beside resident memory, the bytes the program holds from the allocator: when resident memory steps up while
// these stay flat, the allocator kept freed pages, not the program its data. That is why a soak judges growth on the
// heap in use and only reports resident memory.
#include <cstdint>

namespace lmc::devices {

struct ProcessStats {
  double rss_mb = 0;          // resident set size, MiB
  double heap_in_use_mb = 0;  // allocated and not freed (glibc's mallinfo2, ASan's count, Windows' private bytes), MiB
  int fds = 0;                // open file descriptors (Windows: handles)
  int threads = 0;
};

// User plus system CPU time this process has used, in seconds (all its threads).
double process_cpu_seconds();

// Zeros where /proc is not there to read (the soak then cannot judge growth and says so).
ProcessStats read_process_stats();

}  // namespace lmc::devices
