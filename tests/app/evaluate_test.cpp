// Runs the built `lmc evaluate` (lmc::test::cli_path()).
#include <gtest/gtest.h>
#include <algorithm>

#include <filesystem>

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

namespace {

TEST(LmcEvaluate, SplitsByOrientationOnAPoseFile) {
  const auto dir = lmc::test::scratch_dir("cli_evaluate");
  const auto poses = dir / "p.tsv";
  ASSERT_EQ(run_lmc("poses --frames 60 --seed 2 -o " + lmc::test::shell_quote(poses.string()), dir).exit_code, 0);
  const CliRun r =
      run_lmc("evaluate --layout paper-initial --poses " + lmc::test::shell_quote(poses.string()) + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["all"]["frames"], 60);
  EXPECT_EQ(j["horizontal"]["frames"].get<int>() + j["vertical"]["frames"].get<int>(), 60);
  EXPECT_EQ(j["all"]["c"].size(), 5u);
  EXPECT_EQ(j["all"]["coverage"][3]["slot"], "LMC4");
  EXPECT_GE(j["all"]["metric"].get<double>(), 0.0);
  // The text summary carries the same M.
  const CliRun t = run_lmc("evaluate --layout paper-initial --poses " + lmc::test::shell_quote(poses.string()), dir);
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("horizontal poses:"), std::string::npos);
  EXPECT_NE(t.out.find("vertical poses:"), std::string::npos);
}

TEST(LmcEvaluate, RobustTermsAndWhatEachControllerContributes) {
  const auto dir = lmc::test::scratch_dir("cli_evaluate_robust");
  const CliRun r = run_lmc("evaluate --layout paper-optimized --frames 300 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* split : {"all", "horizontal", "vertical"}) {
    EXPECT_EQ(j["robust_terms"][split]["M"], j[split]["metric"]) << split;
  }
  ASSERT_EQ(j["controllers"].size(), 4u);
  // As published, the paper's optimized layout has LMC1 looking away from the hand.
  EXPECT_EQ(j["controllers"][0]["slot"], "LMC1");
  EXPECT_EQ(j["controllers"][0]["seeing_share"], 0.0);
  EXPECT_EQ(j["controllers"][0]["counts"], false);
  EXPECT_EQ(j["controllers"][3]["counts"], true);
  EXPECT_EQ(j["controllers"][0]["seeing_inside_cut_share"], 0.0);
  EXPECT_EQ(j["controllers"][0]["counts_inside_cut"], false);
  EXPECT_LE(j["controllers"][3]["seeing_inside_cut_share"].get<double>(),
            j["controllers"][3]["seeing_share"].get<double>());
  const CliRun t = run_lmc("evaluate --layout paper-optimized --frames 300", dir);
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("NO: the layout is as good without it"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("axis cut"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("the same inside the axis cuts"), std::string::npos) << t.out;
  const auto report = dir / "report";
  const CliRun w = run_lmc(
      "evaluate --layout paper-optimized --frames 300 --report " + lmc::test::shell_quote(report.string()), dir);
  ASSERT_EQ(w.exit_code, 0) << w.err;
  const std::string md = lmc::test::read_text_file(report / "report.md");
  EXPECT_NE(md.find("**LMC1 does not count**"), std::string::npos) << md;
  EXPECT_NE(md.find("## Coverage per reference pose"), std::string::npos) << md;
  // Its pictures, linked from the page, each with the data behind it and a sidecar.
  EXPECT_NE(md.find("](top-view.svg)"), std::string::npos) << md;
  EXPECT_NE(md.find("](finger-coverage.svg)"), std::string::npos) << md;
  for (const char* f : {"top-view.svg", "top-view.csv", "top-view.json", "pose-redundancy.svg", "pose-redundancy.csv",
                        "finger-coverage.svg", "finger-coverage.csv", "finger-coverage.json"}) {
    EXPECT_TRUE(std::filesystem::exists(report / f)) << f;
  }
  EXPECT_NE(lmc::test::read_text_file(report / "top-view.svg").find("LMC4"), std::string::npos);
  // The heatmap: five fingers × ten reference poses × two panels, each cell one row of its CSV.
  const std::string heatmap = lmc::test::read_text_file(report / "finger-coverage.svg");
  size_t cells = 0;
  for (size_t i = heatmap.find("<rect class=\"cell"); i != std::string::npos;
       i = heatmap.find("<rect class=\"cell", i + 1))
    ++cells;
  EXPECT_EQ(cells, 100u);
  const std::string csv = lmc::test::read_text_file(report / "finger-coverage.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 101);
  EXPECT_NE(csv.find("\n1,thumb,palm left,wrist extension,"), std::string::npos) << csv;
}

TEST(LmcEvaluate, UnknownLayoutIsAnError) {
  const auto dir = lmc::test::scratch_dir("cli_evaluate_bad");
  const CliRun r = run_lmc("evaluate --layout no-such-layout --frames 5", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no-such-layout"), std::string::npos) << r.err;
}

}  // namespace
