#pragma once
// What a long recording must not accumulate, read from /proc/self (Linux): resident memory, open
// file descriptors and threads. A soak samples them every second to tell a leak from a plateau.
#include <cstdint>

namespace lmc::devices {

struct ProcessStats {
  double rss_mb = 0;  // resident set size, MiB
  int fds = 0;        // open file descriptors
  int threads = 0;
};

// Zeros where /proc is not there to read (the soak then cannot judge growth and says so).
ProcessStats read_process_stats();

}  // namespace lmc::devices
