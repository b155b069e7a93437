#include "devices/soak/process_stats.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace lmc::devices {

ProcessStats read_process_stats() {
  ProcessStats s;
  // statm: size resident shared … in pages.
  if (std::ifstream statm("/proc/self/statm"); statm) {
    long long size = 0, resident = 0;
    if (statm >> size >> resident)
      s.rss_mb = static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
  }
  std::error_code ec;
  int fds = 0;
  for (std::filesystem::directory_iterator it("/proc/self/fd", ec), end; !ec && it != end; it.increment(ec)) ++fds;
  // The iterator's own descriptor was open while it counted.
  s.fds = fds > 0 ? fds - 1 : 0;
  if (std::ifstream status("/proc/self/status"); status) {
    for (std::string line; std::getline(status, line);) {
      if (line.rfind("Threads:", 0) == 0) {
        s.threads = std::stoi(line.substr(8));
        break;
      }
    }
  }
  return s;
}

}  // namespace lmc::devices
