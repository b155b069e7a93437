// Runs the built `lmc poses` (lmc::test::cli_path()).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace {

using lmc::test::CliRun;
using lmc::test::read_text_file;
using lmc::test::run_lmc;

}  // namespace

#include "core/io/pose_set_tsv.h"

namespace {

TEST(LmcPoses, WritesADeterministicPoseSetThatReadsBack) {
  const auto dir = lmc::test::scratch_dir("cli_poses");
  const std::string a = (dir / "a.tsv").string(), b = (dir / "b.tsv").string(), c = (dir / "c.tsv").string();
  CliRun r = run_lmc("poses --frames 40 --seed 3 -o " + lmc::test::shell_quote(a), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote 40 frames"), std::string::npos) << r.out;
  ASSERT_EQ(run_lmc("poses --frames 40 --seed 3 -o " + lmc::test::shell_quote(b), dir).exit_code, 0);
  ASSERT_EQ(run_lmc("poses --frames 40 --seed 4 -o " + lmc::test::shell_quote(c), dir).exit_code, 0);
  EXPECT_EQ(read_text_file(a), read_text_file(b));
  EXPECT_NE(read_text_file(a), read_text_file(c));
  const lmc::PoseSet set = lmc::load_pose_set(a);
  EXPECT_EQ(set.size(), 40);
  EXPECT_EQ(set.labels.size(), 40u);
  EXPECT_EQ(read_text_file(a).rfind("# lmc-poses 1\n", 0), 0u);
}

TEST(LmcPoses, UsesARecordedHand) {
  const auto hand = lmc::test::reference_file("optimization/Static.txt");
  LMC_REQUIRE_REFERENCE_FILE(hand);
  const auto dir = lmc::test::scratch_dir("cli_poses_hand");
  const std::string out = (dir / "p.tsv").string();
  const CliRun r = run_lmc(
      "poses --frames 5 --hand " + lmc::test::shell_quote(hand.string()) + " -o " + lmc::test::shell_quote(out), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(lmc::load_pose_set(out).description.find("hand="), std::string::npos);
}

TEST(LmcPoses, MissingOutputIsAnError) {
  const auto dir = lmc::test::scratch_dir("cli_poses_bad");
  EXPECT_NE(run_lmc("poses --frames 5", dir).exit_code, 0);
  const CliRun r = run_lmc("poses --frames 5 --hand " + lmc::test::shell_quote((dir / "missing.txt").string()) +
                               " -o " + lmc::test::shell_quote((dir / "p.tsv").string()),
                           dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("missing.txt"), std::string::npos) << r.err;
}

}  // namespace
