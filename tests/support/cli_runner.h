#pragma once
// Runs the built `lmc` binary (cli_path()) the way a user would, capturing stdout and stderr
// separately. Shared by every test under tests/app/.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
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

// Single-quotes `s` for /bin/sh (test paths may hold spaces).
inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// `lmc <args>`; the streams are kept as files in `log_dir` (created when missing). With no
// `log_dir`, a fresh folder is made per call: ctest runs the tests of one binary as parallel
// processes, so fixed names would race. `shell_prefix` runs first in the same shell (e.g.
// "ulimit -f 200 &&" to give lmc a file-size limit).
inline CliRun run_lmc(const std::string& args, std::filesystem::path log_dir = {}, const std::string& shell_prefix = {}) {
  if (log_dir.empty()) {
    std::string pattern = (std::filesystem::temp_directory_path() / "lmc_cli_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) return {};
    log_dir = pattern;
  }
  std::filesystem::create_directories(log_dir);
  const std::string inner = shell_prefix + (shell_prefix.empty() ? "" : " exec ") + shell_quote(cli_path().string()) + " " + args;
  const std::string cmd = "/bin/sh -c " + shell_quote(inner) + " >" + shell_quote((log_dir / "out").string()) + " 2>" +
                          shell_quote((log_dir / "err").string());
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text_file(log_dir / "out");
  r.err = read_text_file(log_dir / "err");
  return r;
}

}  // namespace lmc::test
