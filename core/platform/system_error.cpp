#include "core/platform/system_error.h"

#ifdef _WIN32
#include <windows.h>

#include <algorithm>
#else
#include <cerrno>
#include <cstring>
#endif

namespace lmc::platform {

#ifdef _WIN32
std::string system_error_text(long code) {
  // The wide form, in the user's language, turned into UTF-8: the ANSI form would give a German or
  // Japanese Windows' words in its code page, which the JSON reports refuse.
  wchar_t* text = nullptr;
  const DWORD n =
      FormatMessageW(FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS,
                     nullptr, static_cast<DWORD>(code), 0, reinterpret_cast<LPWSTR>(&text), 0, nullptr);
  std::string out;
  if (n > 0 && text != nullptr) {
    const int bytes = WideCharToMultiByte(CP_UTF8, 0, text, static_cast<int>(n), nullptr, 0, nullptr, nullptr);
    out.resize(static_cast<size_t>(std::max(bytes, 0)));
    if (bytes > 0) WideCharToMultiByte(CP_UTF8, 0, text, static_cast<int>(n), out.data(), bytes, nullptr, nullptr);
  }
  if (text != nullptr) LocalFree(text);
  if (out.empty()) out = "Windows error " + std::to_string(code);
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
