// Runs the built `lmc evaluate` (LMC_CLI_PATH).
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

TEST(LmcEvaluate, SplitsByOrientationOnAPoseFile) {
  const auto dir = lmc::test::scratch_dir("cli_evaluate");
  const auto poses = dir / "p.tsv";
  ASSERT_EQ(lmc_run("poses --frames 60 --seed 2 -o " + quoted(poses.string()), dir).exit_code, 0);
  const CliRun r = lmc_run("evaluate --layout paper-initial --poses " + quoted(poses.string()) + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["all"]["frames"], 60);
  EXPECT_EQ(j["horizontal"]["frames"].get<int>() + j["vertical"]["frames"].get<int>(), 60);
  EXPECT_EQ(j["all"]["c"].size(), 5u);
  EXPECT_EQ(j["all"]["coverage"][3]["slot"], "LMC4");
  EXPECT_GE(j["all"]["metric"].get<double>(), 0.0);
  // The text summary carries the same M.
  const CliRun t = lmc_run("evaluate --layout paper-initial --poses " + quoted(poses.string()), dir);
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("horizontal poses:"), std::string::npos);
  EXPECT_NE(t.out.find("vertical poses:"), std::string::npos);
}

TEST(LmcEvaluate, UnknownLayoutIsAnError) {
  const auto dir = lmc::test::scratch_dir("cli_evaluate_bad");
  const CliRun r = lmc_run("evaluate --layout no-such-layout --frames 5", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no-such-layout"), std::string::npos) << r.err;
}

}  // namespace
