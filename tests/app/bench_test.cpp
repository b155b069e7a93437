// Runs the built `lmc bench` (LMC_CLI_PATH) on a tiny workload: checks the report, not speed.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/support/reference_data.h"

namespace {

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs the built `lmc` with `args`; stdout/stderr are captured in `dir`.
CliRun lmc_run(const std::string& args, const std::filesystem::path& dir) {
  const std::string cmd = quoted(LMC_CLI_PATH) + " " + args + " >" + quoted((dir / "stdout").string()) + " 2>" +
                          quoted((dir / "stderr").string());
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_all(dir / "stdout");
  r.err = read_all(dir / "stderr");
  return r;
}

}  // namespace

namespace {

TEST(LmcBench, JsonHasTheDocumentedKeys) {
  const auto dir = lmc::test::scratch_dir("cli_bench");
  const CliRun r = lmc_run("bench --frames 50 --min-seconds 0.01 --particles 3 --iterations 1 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 50);
  EXPECT_GE(j["threads"].get<int>(), 1);
  ASSERT_EQ(j["cases"].size(), 3u);
  EXPECT_EQ(j["cases"][0]["name"], "paper-initial");
  EXPECT_EQ(j["cases"][2]["name"], "random");
  EXPECT_EQ(j["cases"][2]["layouts"], 30);
  for (const auto& c : j["cases"]) {
    EXPECT_GT(c["single_thread_evals_per_s"].get<double>(), 0.0);
    EXPECT_GT(c["all_threads_evals_per_s"].get<double>(), 0.0);
  }
  EXPECT_EQ(j["search"]["particles"], 3);
  EXPECT_GT(j["search"]["seconds"].get<double>(), 0.0);
}

}  // namespace
