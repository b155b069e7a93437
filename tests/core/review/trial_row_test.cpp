// A trial table row from a processed trial's summary: pooled visibility per
// controller, the mean finger-length difference, the mean absolute ROM difference and a clear lag;
// unknown values stay NaN, never 0.
#include <gtest/gtest.h>

#include <cmath>

#include "core/review/trial_row.h"

namespace lmc {
namespace trial_row_test {  // named: test files share unity batches

nlohmann::json summary_with_vicon() {
  return nlohmann::json::parse(R"({
    "method": "default", "frames": 250, "warnings": ["one"],
    "visibility": [
      {"device": "LMC1", "visible": [10, 10, 10, 10, 10], "hidden": [0, 0, 0, 10, 30], "no_hand": [0,0,0,0,0]},
      {"device": "LMC2", "visible": [0, 0, 0, 0, 0], "hidden": [0, 0, 0, 0, 0], "no_hand": [40,40,40,40,40]}
    ],
    "comparison": {
      "finger_mean_diff_mm": [-10.0, -20.0, null, 0.0, 6.0],
      "rom_diff_deg": [4.0, -2.0, null, null, -6.0, 0.0],
      "lag": {"valid": true, "clear": true, "frames": 3, "ms": 30, "correlation": 0.95}
    }
  })");
}

TEST(TrialRow, ReadsTheHeadlineNumbersFromASummary) {
  const TrialRow r = trial_row("S03", "Opti_Index203", summary_with_vicon(), "");
  EXPECT_EQ(r.subject, "S03");
  EXPECT_EQ(r.layout, "optimized");
  EXPECT_EQ(r.pose, "vertical");
  EXPECT_EQ(r.motion, "index");
  EXPECT_EQ(r.method, "default");
  EXPECT_EQ(r.status, TrialRowStatus::kOk);
  EXPECT_EQ(r.warnings, 1);
  EXPECT_DOUBLE_EQ(r.seconds, 2.5);
  ASSERT_EQ(r.visibility_rate.size(), 2u);
  EXPECT_DOUBLE_EQ(r.visibility_rate[0], 50.0 / 90.0);  // pooled: 50 seen of 90 reported
  EXPECT_TRUE(std::isnan(r.visibility_rate[1]));        // never saw the hand: unknown, not 0 %
  EXPECT_DOUBLE_EQ(r.finger_length_diff_mm, -6.0);      // (−10 − 20 + 0 + 6) / 4: null left out
  EXPECT_DOUBLE_EQ(r.rom_abs_diff_deg, 3.0);            // (4 + 2 + 6 + 0) / 4
  EXPECT_DOUBLE_EQ(r.lag_ms, 30.0);
}

TEST(TrialRow, NoViconFailedAndCancelledTrialsSayWhatTheyAre) {
  nlohmann::json s = summary_with_vicon();
  s.erase("comparison");
  TrialRow r = trial_row("S01", "Naiv_Static101", s, "");
  EXPECT_EQ(r.status, TrialRowStatus::kNoVicon);
  EXPECT_TRUE(std::isnan(r.finger_length_diff_mm));
  EXPECT_TRUE(std::isnan(r.lag_ms));
  r = trial_row("S01", "Naiv_Static101", nullptr, "LMC_Naiv_Static101.raw.txt: line 3: not a number");
  EXPECT_EQ(r.status, TrialRowStatus::kFailed);
  EXPECT_EQ(r.error, "LMC_Naiv_Static101.raw.txt: line 3: not a number");
  EXPECT_TRUE(r.visibility_rate.empty());
  r = trial_row("S01", "Naiv_Static101", nullptr, "", true);
  EXPECT_EQ(r.status, TrialRowStatus::kCancelled);
  EXPECT_STREQ(trial_row_status_name(TrialRowStatus::kNoVicon), "no Vicon");
}

TEST(TrialRow, AnUnclearLagIsUnknown) {
  nlohmann::json s = summary_with_vicon();
  s["comparison"]["lag"]["clear"] = false;
  EXPECT_TRUE(std::isnan(trial_row("S01", "x", s, "").lag_ms));
}

}  // namespace trial_row_test
}  // namespace lmc
