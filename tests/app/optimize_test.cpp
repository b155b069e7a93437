// Runs the built `lmc optimize` (lmc::test::cli_path()) on small searches.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/io/layout_json.h"
#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace {

using lmc::test::CliRun;
using lmc::test::read_text_file;
using lmc::test::run_lmc;

TEST(LmcOptimize, SmallSearchWritesALayoutAndJsonSummary) {
  const auto dir = lmc::test::scratch_dir("cli_optimize");
  const auto out1 = dir / "l1.json", out2 = dir / "l2.json";
  const std::string common =
      "optimize --frames 40 --particles 4 --iterations 2 --devices 3 "
      "--bounds x=-300:300,z=-300:300,rx=-45:45,ry=-90:90 --json --no-progress ";
  const CliRun r1 = run_lmc(common + "--threads 1 -o " + lmc::test::shell_quote(out1.string()), dir);
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  const auto j = nlohmann::json::parse(r1.out);
  EXPECT_EQ(j["status"], "completed");
  EXPECT_EQ(j["summary"]["frames"], 40);
  EXPECT_EQ(j["summary"]["c"].size(), 4u);
  EXPECT_EQ(j["layout_evaluations"], 4 * 3);
  EXPECT_EQ(j["best_cost_history"].size(), 3u);
  const lmc::Layout l1 = lmc::load_layout(out1);
  EXPECT_EQ(l1.device_count(), 3);
  for (const auto& d : l1.devices) {
    EXPECT_LE(std::abs(d.pose.x_mm), 300);
    EXPECT_LE(std::abs(d.pose.rx_deg), 45);
  }
  // Same seed on two threads: the same layout.
  const CliRun r2 = run_lmc(common + "--threads 2 -o " + lmc::test::shell_quote(out2.string()), dir);
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  EXPECT_EQ(lmc::load_layout(out2), l1);
}

// Stopping particles that cannot beat their own best changes nothing but the time: --exhaustive
// writes the same layout and history (2,100 frames: three rounds of 1,024).
TEST(LmcOptimize, ExhaustiveGivesTheSameLayoutAsThePrunedSearch) {
  const auto dir = lmc::test::scratch_dir("cli_optimize_exhaustive");
  const auto pruned = dir / "pruned.json", whole = dir / "whole.json";
  const std::string common = "optimize --frames 2100 --particles 6 --iterations 5 --json --no-progress ";
  const CliRun a = run_lmc(common + "-o " + lmc::test::shell_quote(pruned.string()), dir);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const CliRun b = run_lmc(common + "--exhaustive -o " + lmc::test::shell_quote(whole.string()), dir);
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  EXPECT_EQ(ja["best_cost_history"], jb["best_cost_history"]);
  EXPECT_EQ(lmc::load_layout(pruned), lmc::load_layout(whole));
  EXPECT_EQ(jb["layouts_stopped_early"], 0);
  EXPECT_EQ(jb["device_frame_evaluations"], 6 * 6 * 4 * 2100);
  EXPECT_GT(ja["layouts_stopped_early"].get<int>(), 0);
  EXPECT_LT(ja["device_frame_evaluations"].get<long long>(), jb["device_frame_evaluations"].get<long long>());
}

TEST(LmcOptimize, RobustIsTheDefaultAndSaysWhatMadeTheLayout) {
  const auto dir = lmc::test::scratch_dir("cli_optimize_robust");
  const auto out = dir / "robust.json", study = dir / "study.json";
  const std::string common = "optimize --frames 40 --particles 4 --iterations 2 --devices 3 --json --no-progress ";
  const CliRun r = run_lmc(common + "--starts 2 -o " + lmc::test::shell_quote(out.string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["metric"], "robust");
  ASSERT_EQ(j["starts"].size(), 2u);
  EXPECT_EQ(j["starts"][0]["seed"], 1);
  EXPECT_EQ(j["starts"][1]["seed"], 2);
  EXPECT_EQ(j["layout_evaluations"], 2 * 4 * 3);
  const auto& terms = j["robust_terms"];
  for (const char* key : {"M", "redundancy", "participation", "axis_cut", "centring", "footprint", "inside_cut", "R"}) {
    EXPECT_TRUE(terms.contains(key)) << key;
  }
  EXPECT_EQ(terms["R"], j["starts"][j["best_start"].get<int>()]["best_cost"]);
  const lmc::Layout l = lmc::load_layout(out);
  EXPECT_EQ(l.name, "optimized-robust");
  EXPECT_NE(l.description.find("--metric robust"), std::string::npos) << l.description;
  // Robust searches default to the table: every controller whole on the ±400 mm table top.
  for (const auto& d : l.devices) {
    EXPECT_LE(std::abs(d.pose.x_mm), 360);
    EXPECT_LE(std::abs(d.pose.z_mm), 360);
  }
  const CliRun s = run_lmc(common + "--metric study -o " + lmc::test::shell_quote(study.string()), dir);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto js = nlohmann::json::parse(s.out);
  EXPECT_EQ(js["metric"], "study");
  EXPECT_EQ(js["robust_terms"]["M"], js["summary"]["metric"]);
  EXPECT_EQ(lmc::load_layout(study).name, "optimized-study");
  const CliRun bad = run_lmc(common + "--metric best -o " + lmc::test::shell_quote(study.string()), dir);
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("--metric"), std::string::npos) << bad.err;
}

TEST(LmcOptimize, TextSummaryAndLocks) {
  const auto dir = lmc::test::scratch_dir("cli_optimize_text");
  const auto out = dir / "l.json";
  const CliRun r = run_lmc(
      "optimize --frames 30 --particles 3 --iterations 1 --start paper-initial --lock LMC2 "
      "--lock LMC3:x+z -o " +
          lmc::test::shell_quote(out.string()),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("M = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("c_0 = "), std::string::npos);
  EXPECT_NE(r.out.find("seen by nobody"), std::string::npos);
  EXPECT_NE(r.out.find("per second"), std::string::npos);
  const lmc::Layout start = lmc::load_layout_or_preset("paper-initial");
  const lmc::Layout got = lmc::load_layout(out);
  EXPECT_EQ(got.devices[1].pose, start.devices[1].pose);
  EXPECT_EQ(got.devices[2].pose.x_mm, start.devices[2].pose.x_mm);
  EXPECT_EQ(got.devices[2].pose.z_mm, start.devices[2].pose.z_mm);
}

TEST(LmcOptimize, StartLayoutKeepsItsSensorRangeUnlessOverridden) {
  const auto dir = lmc::test::scratch_dir("cli_optimize_range");
  lmc::Layout start = lmc::load_layout_or_preset("paper-initial");
  for (auto& d : start.devices) d.sensor.range_mm = 400.0;
  lmc::save_layout(start, dir / "start.json");
  const std::string common = "optimize --frames 20 --particles 2 --iterations 1 --no-progress --start " +
                             lmc::test::shell_quote((dir / "start.json").string());
  ASSERT_EQ(run_lmc(common + " -o " + lmc::test::shell_quote((dir / "a.json").string()), dir).exit_code, 0);
  EXPECT_EQ(lmc::load_layout(dir / "a.json").devices.front().sensor.range_mm, 400.0);
  ASSERT_EQ(run_lmc(common + " --range-mm 550 -o " + lmc::test::shell_quote((dir / "b.json").string()), dir).exit_code,
            0);
  EXPECT_EQ(lmc::load_layout(dir / "b.json").devices.front().sensor.range_mm, 550.0);
}

TEST(LmcOptimize, BadBoundsAreReported) {
  const auto dir = lmc::test::scratch_dir("cli_optimize_bad");
  const CliRun r =
      run_lmc("optimize --frames 10 --bounds x=9:1 -o " + lmc::test::shell_quote((dir / "l.json").string()), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--bounds"), std::string::npos) << r.err;
  const CliRun r2 = run_lmc(
      "optimize --frames 10 --start paper-initial --lock LMC9 -o " + lmc::test::shell_quote((dir / "l.json").string()),
      dir);
  EXPECT_EQ(r2.exit_code, 1);
  EXPECT_NE(r2.err.find("LMC9"), std::string::npos) << r2.err;
}

}  // namespace
