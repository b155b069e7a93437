#ifdef _WIN32
#include <windows.h>
// After windows.h, which they need.
#include <psapi.h>
#include <tlhelp32.h>

#include "devices/soak/process_stats.h"

namespace lmc::devices {

double process_cpu_seconds() {
  FILETIME created{}, exited{}, kernel{}, user{};
  if (!GetProcessTimes(GetCurrentProcess(), &created, &exited, &kernel, &user)) return 0;
  // FILETIME counts 100 ns ticks.
  const auto ticks = [](const FILETIME& t) {
    return static_cast<double>((static_cast<unsigned long long>(t.dwHighDateTime) << 32) | t.dwLowDateTime);
  };
  return (ticks(kernel) + ticks(user)) * 1e-7;
}

ProcessStats read_process_stats() {
  ProcessStats s;
  const HANDLE self = GetCurrentProcess();
  PROCESS_MEMORY_COUNTERS_EX memory{};
  memory.cb = sizeof memory;
  if (GetProcessMemoryInfo(self, reinterpret_cast<PROCESS_MEMORY_COUNTERS*>(&memory), sizeof memory)) {
    s.rss_mb = static_cast<double>(memory.WorkingSetSize) / (1024.0 * 1024.0);
    // The bytes committed to this process alone: the heap and the threads' stacks. The C runtime
    // has no cheap count of the heap in use; a leak grows this as it would the heap.
    s.heap_in_use_mb = static_cast<double>(memory.PrivateUsage) / (1024.0 * 1024.0);
  }
  DWORD handles = 0;
  if (GetProcessHandleCount(self, &handles)) s.fds = static_cast<int>(handles);
  const HANDLE snapshot = CreateToolhelp32Snapshot(TH32CS_SNAPTHREAD, 0);
  if (snapshot != INVALID_HANDLE_VALUE) {
    const DWORD pid = GetCurrentProcessId();
    THREADENTRY32 entry{};
    entry.dwSize = sizeof entry;
    for (BOOL more = Thread32First(snapshot, &entry); more; more = Thread32Next(snapshot, &entry))
      if (entry.th32OwnerProcessID == pid) ++s.threads;
    CloseHandle(snapshot);
  }
  return s;
}

}  // namespace lmc::devices
#endif
