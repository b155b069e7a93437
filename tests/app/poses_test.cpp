// Runs the built `lmc poses` (LMC_CLI_PATH).
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

#include "core/io/pose_set_tsv.h"

namespace {

TEST(LmcPoses, WritesADeterministicPoseSetThatReadsBack) {
  const auto dir = lmc::test::scratch_dir("cli_poses");
  const std::string a = (dir / "a.tsv").string(), b = (dir / "b.tsv").string(), c = (dir / "c.tsv").string();
  CliRun r = lmc_run("poses --frames 40 --seed 3 -o " + quoted(a), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote 40 frames"), std::string::npos) << r.out;
  ASSERT_EQ(lmc_run("poses --frames 40 --seed 3 -o " + quoted(b), dir).exit_code, 0);
  ASSERT_EQ(lmc_run("poses --frames 40 --seed 4 -o " + quoted(c), dir).exit_code, 0);
  EXPECT_EQ(read_all(a), read_all(b));
  EXPECT_NE(read_all(a), read_all(c));
  const lmc::PoseSet set = lmc::load_pose_set(a);
  EXPECT_EQ(set.size(), 40);
  EXPECT_EQ(set.labels.size(), 40u);
  EXPECT_EQ(read_all(a).rfind("# lmc-poses 1\n", 0), 0u);
}

TEST(LmcPoses, UsesARecordedHand) {
  const auto hand = lmc::test::reference_file("optimization/Static.txt");
  LMC_REQUIRE_REFERENCE_FILE(hand);
  const auto dir = lmc::test::scratch_dir("cli_poses_hand");
  const std::string out = (dir / "p.tsv").string();
  const CliRun r = lmc_run("poses --frames 5 --hand " + quoted(hand.string()) + " -o " + quoted(out), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(lmc::load_pose_set(out).description.find("hand="), std::string::npos);
}

TEST(LmcPoses, MissingOutputIsAnError) {
  const auto dir = lmc::test::scratch_dir("cli_poses_bad");
  EXPECT_NE(lmc_run("poses --frames 5", dir).exit_code, 0);
  const CliRun r = lmc_run("poses --frames 5 --hand " + quoted((dir / "missing.txt").string()) + " -o " +
                            quoted((dir / "p.tsv").string()),
                        dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("missing.txt"), std::string::npos) << r.err;
}

}  // namespace
