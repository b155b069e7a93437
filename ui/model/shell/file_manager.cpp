#include "ui/model/shell/file_manager.h"

#ifdef _WIN32
#include <windows.h>
// After windows.h, which it needs.
#include <shellapi.h>

#include "core/platform/system_error.h"
#else
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>
#endif

namespace lmc::ui {

bool open_in_file_manager(const std::filesystem::path& folder, std::string* error, const std::string& program) {
  const auto fail = [error](const std::string& why) {
    if (error != nullptr) *error = why;
    return false;
  };
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return fail("no such folder: " + folder.string());
#ifdef _WIN32
  // xdg-open is the Linux desktop's opener; on Windows that is Explorer, reached through the shell
  // (as a double click would). Another program is started with the folder as its one argument.
  const std::wstring opener =
      program == "xdg-open" ? std::wstring(L"explorer.exe") : std::filesystem::path(program).wstring();
  const auto result = reinterpret_cast<INT_PTR>(ShellExecuteW(
      nullptr, L"open", opener.c_str(), (L"\"" + folder.wstring() + L"\"").c_str(), nullptr, SW_SHOWNORMAL));
  // ShellExecute returns a value above 32 when it started the program.
  if (result > 32) return true;
  if (result == ERROR_FILE_NOT_FOUND || result == ERROR_PATH_NOT_FOUND) return fail(program + " is not installed");
  return fail("could not start " + program + ": " + platform::last_system_error());
#else
  // A shell starts the opener in the background and exits at once, so there is one short wait
  // here and no child left to reap; the folder and the program are arguments, never parsed.
  const std::string script =
      "command -v \"$0\" >/dev/null 2>&1 || exit 127; \"$0\" \"$1\" >/dev/null 2>&1 </dev/null &";
  std::vector<std::string> args{"/bin/sh", "-c", script, program, folder.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (const int rc = ::posix_spawn(&pid, "/bin/sh", nullptr, nullptr, argv.data(), environ); rc != 0) {
    return fail(std::string("could not start /bin/sh: ") + std::strerror(rc));
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127) return fail(program + " is not installed");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return fail("could not start " + program);
  return true;
#endif
}

}  // namespace lmc::ui
