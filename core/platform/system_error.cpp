#include "core/platform/system_error.h"

#ifdef _WIN32
#include <windows.h>
#else
#include <cerrno>
#include <cstring>
#endif

namespace lmc::platform {

#ifdef _WIN32
std::string system_error_text(long code) {
  char* text = nullptr;
  const DWORD n =
      FormatMessageA(FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS,
                     nullptr, static_cast<DWORD>(code), 0, reinterpret_cast<LPSTR>(&text), 0, nullptr);
  std::string out = n > 0 && text != nullptr ? std::string(text, n) : "Windows error " + std::to_string(code);
  if (text != nullptr) LocalFree(text);
  // FormatMessage ends its sentences with ".\r\n"; the callers go on after it.
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r' || out.back() == ' ' || out.back() == '.'))
    out.pop_back();
  return out;
}

std::string last_system_error() {
  return system_error_text(static_cast<long>(GetLastError()));
}
#else
std::string system_error_text(long code) {
  return std::strerror(static_cast<int>(code));
}

std::string last_system_error() {
  return system_error_text(errno);
}
#endif

}  // namespace lmc::platform
