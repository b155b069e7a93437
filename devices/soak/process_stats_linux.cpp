#ifndef _WIN32
#include <sys/resource.h>
#include <unistd.h>

#include <cstddef>
#if defined(__SANITIZE_ADDRESS__)
#define LMC_ASAN_HEAP 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LMC_ASAN_HEAP 1
#endif
#endif
#if defined(LMC_ASAN_HEAP)
// The sanitizer runtime's own count of the bytes it has handed out and not taken back. Declared
// here: GCC does not ship clang's <sanitizer/allocator_interface.h>, though its runtime has it.
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#elif defined(__GLIBC__)
#include <malloc.h>
#endif

#include <filesystem>
#include <fstream>
#include <string>

#include "devices/soak/process_stats.h"

namespace lmc::devices {

double process_cpu_seconds() {
  rusage u{};
  ::getrusage(RUSAGE_SELF, &u);
  const auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; };
  return s(u.ru_utime) + s(u.ru_stime);
}

ProcessStats read_process_stats() {
  ProcessStats s;
  // statm: size resident shared … in pages.
  if (std::ifstream statm("/proc/self/statm"); statm) {
    long long size = 0, resident = 0;
    if (statm >> size >> resident)
      s.rss_mb = static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
  }
#if defined(LMC_ASAN_HEAP)
  // Under AddressSanitizer its allocator serves every malloc and glibc's arenas stay empty.
  s.heap_in_use_mb = static_cast<double>(__sanitizer_get_current_allocated_bytes()) / (1024.0 * 1024.0);
#elif defined(__GLIBC__)
  // uordblks: bytes in use in the arenas; hblkhd: bytes in blocks the allocator mapped on their own.
  const struct mallinfo2 heap = ::mallinfo2();
  s.heap_in_use_mb = static_cast<double>(heap.uordblks + heap.hblkhd) / (1024.0 * 1024.0);
#endif
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
#endif
