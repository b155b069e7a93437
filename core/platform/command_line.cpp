#include "core/platform/command_line.h"

#ifdef _WIN32
#include <windows.h>
// After windows.h, which it needs.
#include <shellapi.h>

#include <cwchar>
#endif

namespace lmc::platform {

#ifdef _WIN32
namespace {

std::string to_utf8(const wchar_t* text, int length) {
  const int bytes = WideCharToMultiByte(CP_UTF8, 0, text, length, nullptr, 0, nullptr, nullptr);
  std::string out(static_cast<size_t>(bytes > 0 ? bytes : 0), '\0');
  if (bytes > 0) WideCharToMultiByte(CP_UTF8, 0, text, length, out.data(), bytes, nullptr, nullptr);
  return out;
}

// Whether `arg` reaches main() and then std::filesystem::path unchanged. main() gets it in the
// ANSI code page, and a path made of a std::string takes each byte for the character of that
// number (MinGW's C runtime in its "C" locale). So each character must be ASCII, or one the code
// page writes as the byte of its own number: the Latin-1 letters (ü, é, ß, ø) in Windows-1252, the
// Western European code page; in any other, ASCII only.
bool intact_in_code_page(const wchar_t* arg, int length) {
  for (int i = 0; i < length; ++i) {
    const wchar_t c = arg[i];
    if (c < 0x80) continue;
    if (c > 0xff) return false;
    char byte = 0;
    BOOL lost = FALSE;
    const int n = WideCharToMultiByte(CP_ACP, WC_NO_BEST_FIT_CHARS, &c, 1, &byte, 1, nullptr, &lost);
    if (n != 1 || lost != FALSE || static_cast<unsigned char>(byte) != c) return false;
  }
  return true;
}

}  // namespace

std::string arguments_changed_by_code_page() {
  int count = 0;
  wchar_t** args = CommandLineToArgvW(GetCommandLineW(), &count);
  if (args == nullptr) return {};
  std::string problem;
  for (int i = 1; i < count && problem.empty(); ++i) {
    const int length = static_cast<int>(std::wcslen(args[i]));
    if (intact_in_code_page(args[i], length)) continue;
    problem = "argument " + std::to_string(i) + " (\"" + to_utf8(args[i], length) +
              "\") holds characters that would reach this program changed (Windows passes its arguments in code "
              "page " +
              std::to_string(GetACP()) +
              "); nothing was done. Rename the folder or file, or give its short name (dir /x shows it)";
  }
  LocalFree(args);
  return problem;
}
#else
std::string arguments_changed_by_code_page() {
  return {};
}
#endif

}  // namespace lmc::platform
