#ifndef _WIN32
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "ui/model/shell/file_manager.h"

namespace lmc::ui {

bool open_in_file_manager(const std::filesystem::path& folder, std::string* error, const std::string& program) {
  const auto fail = [error](const std::string& why) {
    if (error != nullptr) *error = why;
    return false;
  };
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return fail("no such folder: " + folder.string());
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
}

}  // namespace lmc::ui
#endif
