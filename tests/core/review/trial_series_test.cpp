// The Review tab's time series of one trial on the study's real trial: the fused and
// Vicon series are exactly processing's per-frame measures, each controller's labels are the
// ray-traced ones, one time axis; the CSV behind the plots has a column per series and empty
// cells, never 0, for missing values.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/io/layout_json.h"
#include "core/io/vicon_mapping.h"
#include "core/processing/batch.h"
#include "core/review/trial_series.h"
#include "tests/support/reference_data.h"
#include "tests/support/shared_real_trial.h"

namespace lmc {
namespace trial_series_test {  // named: test files share unity batches

size_t count_fields(const std::string& line) {
  return static_cast<size_t>(std::count(line.begin(), line.end(), ',')) + 1;
}

TEST(TrialSeries, TheSharedTrialsSeriesAreProcessingsOwnMeasures) {
  const auto files = test::shared_real_trial_files();
  LMC_REQUIRE_REFERENCE_FILE(files.lmc);
  LMC_REQUIRE_REFERENCE_FILE(files.trc);
  const test::SharedRealTrial trial = test::load_shared_real_trial();
  const TrialAnalysis r =
      process_trial("Naiv_Static101", trial.recording, trial.layout, &trial.vicon, ProcessOptions{});
  const TrialSeries s = trial_series(r);
  ASSERT_EQ(s.frames(), 50);
  EXPECT_DOUBLE_EQ(s.time_s.front(), 0.0);
  EXPECT_NEAR(s.time_s.back(), 0.49, 1e-12);
  ASSERT_TRUE(s.has_vicon);
  for (int f = 0; f < s.frames(); ++f) {
    for (int a = 0; a < kNumAngles; ++a) {
      const double fused = r.lmc_frames[f].angle_deg[a], truth = r.vicon_frames[f].angle_deg[a];
      if (std::isnan(fused))
        EXPECT_TRUE(std::isnan(s.fused.angle_deg[a][f]));
      else
        EXPECT_DOUBLE_EQ(s.fused.angle_deg[a][f], fused);
      if (std::isnan(truth))
        EXPECT_TRUE(std::isnan(s.vicon.angle_deg[a][f]));
      else
        EXPECT_DOUBLE_EQ(s.vicon.angle_deg[a][f], truth);
    }
  }
  ASSERT_EQ(s.devices.size(), 4u);
  for (size_t d = 0; d < 4; ++d) {
    EXPECT_EQ(s.devices[d].device_id, static_cast<int>(d) + 1);
    for (int f = 0; f < s.frames(); ++f) {
      for (int k = 0; k < kNumDigits; ++k) ASSERT_EQ(s.devices[d].label[k][f], r.labels[d][f][k]);
    }
  }
  // The study's layout sees this static hand from LMC1 with finite angles: its own series exist.
  EXPECT_TRUE(std::isfinite(s.devices[0].measures.finger_mm[1][10]));
  // The visibility table is the labels' count: the strips and the table cannot disagree.
  int seen = 0;
  for (int f = 0; f < s.frames(); ++f) seen += s.devices[0].label[1][f] == 1 ? 1 : 0;
  EXPECT_EQ(seen, r.visibility[0].n_visible[1]);
}

TEST(TrialSeries, TheCsvHasAColumnPerSeriesAndEmptyCellsForMissingValues) {
  TrialSeries s;
  s.trial = "t";
  s.time_s = {0.0, 0.01};
  for (auto& v : s.fused.angle_deg) v = {1.5, std::nan("")};
  for (auto& v : s.fused.finger_mm) v = {70.25, 71.0};
  DeviceSeries d;
  d.device_id = 2;
  for (auto& v : d.measures.angle_deg) v = {std::nan(""), 3.0};
  for (auto& v : d.measures.finger_mm) v = {std::nan(""), std::nan("")};
  for (auto& l : d.label) l = {-1, 1};
  s.devices.push_back(d);
  const std::string csv = trial_series_csv(s);
  std::istringstream in(csv);
  std::string header, row0, row1;
  std::getline(in, header);
  std::getline(in, row0);
  std::getline(in, row1);
  // time + 11 fused + 11 of LMC2 + 5 labels; no Vicon columns without Vicon.
  EXPECT_EQ(count_fields(header), 28u);
  EXPECT_EQ(count_fields(row0), 28u);
  EXPECT_EQ(header.find("vicon"), std::string::npos);
  EXPECT_EQ(header.substr(0, 26), "time_s,fused_index_mcp_deg");
  EXPECT_NE(header.find("lmc2_pinky_label"), std::string::npos);
  EXPECT_EQ(row0.substr(0, 14), "0.0000,1.5000,");
  // Row 1: the fused angles are missing — six empty cells, never 0.
  EXPECT_EQ(row1.substr(0, 14), "0.0100,,,,,,,7");
  EXPECT_EQ(row0.substr(row0.size() - 14), "-1,-1,-1,-1,-1");
  EXPECT_EQ(row1.substr(row1.size() - 9), "1,1,1,1,1");
  EXPECT_STREQ(label_word(0), "internal model");
}

}  // namespace trial_series_test
}  // namespace lmc
