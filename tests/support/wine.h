#pragma once
// Whether a test runs under Wine, for the few Windows behaviours Wine does not reproduce (each
// test that asks says which and why). False on Linux and on Windows itself.
#ifdef _WIN32
#include <windows.h>
#endif

namespace lmc::test {

inline bool running_under_wine() {
#ifdef _WIN32
  // Wine's ntdll exports its version; Windows' does not.
  const HMODULE ntdll = GetModuleHandleW(L"ntdll.dll");
  return ntdll != nullptr && GetProcAddress(ntdll, "wine_get_version") != nullptr;
#else
  return false;
#endif
}

}  // namespace lmc::test
