#ifdef _WIN32
#include <windows.h>
// After windows.h, which it needs.
#include <shellapi.h>

#include "core/platform/system_error.h"
#include "ui/model/shell/file_manager.h"

namespace lmc::ui {

bool open_in_file_manager(const std::filesystem::path& folder, std::string* error, const std::string& program) {
  const auto fail = [error](const std::string& why) {
    if (error != nullptr) *error = why;
    return false;
  };
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return fail("no such folder: " + folder.string());
  // xdg-open is the Linux desktop's opener; on Windows that is Explorer, reached through the shell
  // (as a double click would). Another program is started with the folder as its one argument.
  const std::wstring opener = program == "xdg-open" ? std::wstring(L"explorer.exe") : std::filesystem::path(program).wstring();
  const auto result = reinterpret_cast<INT_PTR>(
      ShellExecuteW(nullptr, L"open", opener.c_str(), (L"\"" + folder.wstring() + L"\"").c_str(), nullptr, SW_SHOWNORMAL));
  // ShellExecute returns a value above 32 when it started the program.
  if (result > 32) return true;
  if (result == ERROR_FILE_NOT_FOUND || result == ERROR_PATH_NOT_FOUND) return fail(program + " is not installed");
  return fail("could not start " + program + ": " + platform::last_system_error());
}

}  // namespace lmc::ui
#endif
