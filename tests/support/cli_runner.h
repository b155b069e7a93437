#pragma once
// Runs the built `lmc` binary (cli_path()) the way a user would, capturing stdout and stderr
// separately. Shared by every test under tests/app/.
#ifdef _WIN32
#include <windows.h>
#else
#include <sys/wait.h>
#include <unistd.h>
#endif

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>

#include "tests/support/build_paths.h"

namespace lmc::test {

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;

  std::string all() const { return out + err; }
};

inline std::string read_text_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Quotes `s` for the shell run_lmc uses (test paths may hold spaces): single quotes for /bin/sh;
// double quotes for cmd.exe on Windows (where a path cannot hold a double quote).
inline std::string shell_quote(const std::string& s) {
#ifdef _WIN32
  return "\"" + s + "\"";
#else
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
#endif
}

// The shell_prefix for run_lmc that sets one environment variable for that run: `export` in
// /bin/sh, `set` in cmd.exe.
inline std::string env_prefix(const std::string& name, const std::string& value) {
#ifdef _WIN32
  return "set \"" + name + "=" + value + "\" && ";
#else
  return "export " + name + "=" + shell_quote(value) + " &&";
#endif
}

// A fresh folder of its own for one run's streams.
inline std::filesystem::path fresh_log_dir() {
#ifdef _WIN32
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() /
                   ("lmc_cli_" + std::to_string(GetCurrentProcessId()) + "_" + std::to_string(++counter));
  std::filesystem::remove_all(dir);
  return std::filesystem::create_directories(dir) ? dir : std::filesystem::path();
#else
  std::string pattern = (std::filesystem::temp_directory_path() / "lmc_cli_XXXXXX").string();
  return ::mkdtemp(pattern.data()) == nullptr ? std::filesystem::path() : std::filesystem::path(pattern);
#endif
}

// `lmc <args>`; the streams are kept as files in `log_dir` (created when missing). With no
// `log_dir`, a fresh folder is made per call: ctest runs the tests of one binary as parallel
// processes, so fixed names would race. `shell_prefix` runs first in the same shell (e.g.
// "ulimit -f 200 &&" to give lmc a file-size limit).
// `launcher` runs lmc through another program (e.g. "setpriv --reuid=65534 …" to run it unprivileged).
inline CliRun run_lmc(const std::string& args, std::filesystem::path log_dir = {}, const std::string& shell_prefix = {},
                      const std::string& launcher = {}) {
  const bool own_log_dir = log_dir.empty();
  if (own_log_dir) {
    log_dir = fresh_log_dir();
    if (log_dir.empty()) return {};
  }
  std::filesystem::create_directories(log_dir);
#ifdef _WIN32
  // cmd.exe /c keeps a command line wrapped in one more pair of quotes as it is (its rule for a
  // line that starts with a quote would otherwise strip the program's).
  const std::string cmd =
      "\"" + shell_prefix + (launcher.empty() ? "" : launcher + " ") + shell_quote(cli_path().string()) + " " + args +
      " >" + shell_quote((log_dir / "out").string()) + " 2>" + shell_quote((log_dir / "err").string()) + "\"";
  CliRun r;
  // -1 with errno set: cmd.exe itself could not be started, so nothing ran. Seen once under Wine
  // while other test processes were starting programs too (the cause was not found); such a start
  // is tried again, and a third failure is said in `err`. A program that ran and failed, or
  // crashed (an exception code, never -1), is never run again.
  std::string launch_error;
  for (int attempt = 0; attempt < 3; ++attempt) {
    errno = 0;
    r.exit_code = std::system(cmd.c_str());
    if (r.exit_code != -1 || errno == 0) break;
    launch_error = std::string("cannot start cmd.exe: ") + std::strerror(errno) + "\n";
    Sleep(200);
  }
#else
  const std::string inner = shell_prefix + (shell_prefix.empty() ? "" : " exec ") +
                            (launcher.empty() ? "" : launcher + " ") + shell_quote(cli_path().string()) + " " + args;
  const std::string cmd = "/bin/sh -c " + shell_quote(inner) + " >" + shell_quote((log_dir / "out").string()) + " 2>" +
                          shell_quote((log_dir / "err").string());
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
#endif
  r.out = read_text_file(log_dir / "out");
  r.err = read_text_file(log_dir / "err");
#ifdef _WIN32
  if (r.exit_code == -1) r.err += launch_error;
  // The streams are text: Windows' C runtime ends their lines with CR LF; the tests compare lines.
  for (std::string* text : {&r.out, &r.err}) {
    size_t at = 0;
    while ((at = text->find("\r\n", at)) != std::string::npos) text->erase(at, 1);
  }
#endif
  if (own_log_dir) {
    // Both streams are in `r` now; a folder of our own making is not left behind in /tmp.
    std::error_code ec;
    std::filesystem::remove_all(log_dir, ec);
  }
  return r;
}

#ifndef _WIN32
// Starts `lmc args` as a child process, not waited for (the caller kills or waits for it); its
// streams go to files in `logs`.
inline pid_t spawn_lmc(const std::string& args, const std::filesystem::path& logs) {
  std::filesystem::create_directories(logs);
  const std::string cmd = "exec " + shell_quote(cli_path().string()) + " " + args + " >" +
                          shell_quote((logs / "out").string()) + " 2>" + shell_quote((logs / "err").string()) +
                          " </dev/null";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}
#endif

// Complete rows (lines ending in a newline) of a recording, not counting its header line.
inline size_t complete_rows(const std::filesystem::path& raw) {
  std::ifstream in(raw);
  size_t rows = 0;
  std::string line;
  while (std::getline(in, line)) rows += in.eof() ? 0 : 1;
  return rows > 0 ? rows - 1 : 0;
}

}  // namespace lmc::test
