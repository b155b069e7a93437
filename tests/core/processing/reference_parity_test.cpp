// Reference parity: the study's pipeline on its own validation trial reproduces the
// authors' result file — every length and angle within 0.01 mm / 0.01°, the visibility table
// exactly. Reads the study's data folder (skips, saying so, when absent).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/trc.h"
#include "core/io/vicon_mapping.h"
#include "core/processing/batch.h"
#include "core/processing/trial_pipeline.h"
#include "core/results/trial_outputs.h"
#include "tests/support/reference_data.h"
#include "tests/support/shared_real_trial.h"

namespace lmc {
namespace {

// The authors' file: numeric rows in order of appearance (tab-separated numbers only).
std::vector<std::vector<double>> numeric_rows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || !(std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '-' || line[0] == 'n'))
      continue;
    std::istringstream ls(line);
    std::vector<double> row;
    std::string cell;
    bool numeric = true;
    while (std::getline(ls, cell, '\t')) {
      try {
        row.push_back(cell == "nan" ? kNaN : std::stod(cell));
      } catch (...) {
        numeric = false;
      }
    }
    if (numeric && !row.empty()) rows.push_back(row);
  }
  return rows;
}

TEST(ReferenceParity, Subject1NaivStatic101MatchesAuthorsResults) {
  const auto files = test::shared_real_trial_files();
  const auto results_file = test::reference_file("validation/Subject1_Naiv.results.txt");
  LMC_REQUIRE_REFERENCE_FILE(files.lmc);
  LMC_REQUIRE_REFERENCE_FILE(files.trc);
  LMC_REQUIRE_REFERENCE_FILE(results_file);

  const auto [rec, vicon, layout] = test::load_shared_real_trial();
  ProcessOptions o;
  o.method = FusionMethod::kReference;
  TrialAnalysis r = process_trial("Naiv_Static101", rec, layout, &vicon, o);
  r.lmc_source = files.lmc.string();
  r.vicon_source = files.trc.string();
  EXPECT_EQ(r.fused.frame_count, 50);  // Vicon's 100 rows trimmed to the LMC's 50 steps

  std::ifstream in(results_file);
  std::stringstream ss;
  ss << in.rdbuf();
  const auto expected = numeric_rows(ss.str());
  const auto actual = numeric_rows(format_results_text(r));
  ASSERT_EQ(actual.size(), expected.size());
  // Rows 0–8: LMC stats; 9–24: visibility (4 devices × 4 rows); 25–33: Vicon stats.
  for (size_t i = 0; i < expected.size(); ++i) {
    ASSERT_EQ(actual[i].size(), expected[i].size()) << "row " << i;
    const bool visibility = i >= 9 && i < 25;
    for (size_t k = 0; k < expected[i].size(); ++k) {
      if (visibility) {
        EXPECT_EQ(actual[i][k], expected[i][k]) << "visibility row " << i << " col " << k;
      } else {
        EXPECT_NEAR(actual[i][k], expected[i][k], 0.01) << "row " << i << " col " << k;
      }
    }
  }
  // The published headline numbers (docs/algorithms/study.md).
  EXPECT_NEAR(r.lmc_stats.finger_mean[0], 47.83, 0.005);
  EXPECT_NEAR(r.vicon_stats.finger_mean[2], 100.15, 0.005);
  // The report names the trial as the authors' does, whichever stage of the file was given.
  const std::string text = format_results_text(r);
  EXPECT_EQ(text.substr(text.find('\n') + 1, 36), "Filename:\tInterp_LMC_Naiv_Static101\n");
  r.lmc_source = test::reference_file("validation/Interp_LMC_Naiv_Static101.raytraced.txt").string();
  const std::string from_raytraced = format_results_text(r);
  EXPECT_EQ(from_raytraced.substr(from_raytraced.find('\n') + 1, 36), "Filename:\tInterp_LMC_Naiv_Static101\n");
}

TEST(ReferenceParity, RawRecordingResamplesToPlausibleGrid) {
  const auto raw = test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(raw);
  const LmcRecording rec = read_lmc_recording(raw);
  ResampleReport report;
  const GridTrial g = resample_recording(rec, {}, &report);
  ASSERT_EQ(g.devices.size(), 4u);
  // devices/leapc/README.md: ≈5.0–5.1 s per device, ≈24 Hz each.
  EXPECT_GE(g.frame_count, 495);
  EXPECT_LE(g.frame_count, 520);
  for (const auto& s : report.devices) {
    EXPECT_GT(s.mean_rate_hz, 11.0);
    EXPECT_LT(s.mean_rate_hz, 34.0);
  }
}

}  // namespace
}  // namespace lmc
