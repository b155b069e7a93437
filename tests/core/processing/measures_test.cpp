#include <gtest/gtest.h>

#include <cmath>

#include "core/processing/compare.h"
#include "core/processing/measures.h"
#include "core/processing/trial_tag.h"

namespace lmc {
namespace {

// A straight hand along −z with known phalanx lengths, index bent 90° at the PIP.
HandTrack straight_hand(int frames) {
  HandTrack t(frames);
  for (int f = 0; f < frames; ++f) {
    t.at(f, kPalm) = Vec3(0, 0, -40);
    t.at(f, kPalmNormal) = Vec3(0, -1, 0);
    t.at(f, kPalmDirection) = Vec3(0, 0, -1);
    t.at(f, kElbow) = Vec3(0, 0, 200);
    t.at(f, kWrist) = Vec3(0, 0, 0);
    for (int d = 0; d < kNumDigits; ++d) {
      const double x = 20.0 * d;
      double z = -80;
      t.at(f, digit_point(d, 0)) = Vec3(x, 0, -10);
      for (int j = 1; j < kJointsPerDigit; ++j) {
        t.at(f, digit_point(d, j)) = Vec3(x, 0, z);
        z -= 10.0 * j;  // segments 10, 20, 30 mm after Proxi
      }
    }
    // Index: Inter → Dist goes down (−y) instead of forward: PIP angle 90°.
    const Vec3 inter = t.at(f, digit_point(1, 2));
    t.at(f, digit_point(1, 3)) = inter + Vec3(0, -20, 0);
    t.at(f, digit_point(1, 4)) = t.at(f, digit_point(1, 3)) + Vec3(0, -30, 0);
  }
  return t;
}

TEST(Measures, LengthsAndAnglesOfAKnownHand) {
  const HandTrack t = straight_hand(3);
  const FrameMeasures m = measure_frame(t, 0);
  EXPECT_DOUBLE_EQ(m.segment_mm[0], 20.0);  // thumb Inter→Dist
  EXPECT_DOUBLE_EQ(m.segment_mm[1], 30.0);
  EXPECT_DOUBLE_EQ(m.finger_mm[0], 50.0);   // thumb: two segments
  EXPECT_DOUBLE_EQ(m.finger_mm[1], 60.0);   // others: three
  EXPECT_NEAR(m.angle_deg[0], 0.0, 1e-6);   // index MCP straight
  EXPECT_NEAR(m.angle_deg[1], 90.0, 1e-9);  // index PIP
  EXPECT_NEAR(m.angle_deg[2], 0.0, 1e-6);   // index DIP
  // Wrist: elbow→wrist is −z, wrist→palm is −z: 0°.
  EXPECT_NEAR(m.angle_deg[5], 0.0, 1e-6);
  // Zero-length segment → 0° (as the study), NaN point → NaN.
  EXPECT_EQ(joint_angle_deg(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(1, 0, 0)), 0.0);
  EXPECT_TRUE(std::isnan(joint_angle_deg(Vec3::Constant(kNaN), Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(1, 0, 0))));
}

TEST(Measures, StatisticsSkipNaNFrames) {
  HandTrack t = straight_hand(4);
  t.at(2, digit_point(2, 4)) = Vec3::Constant(kNaN);
  t.at(3, digit_point(2, 4)) += Vec3(0, 0, -6);  // middle distal 36 mm in frame 3
  const MeasureStats s = summarize(measure_track(t));
  EXPECT_DOUBLE_EQ(s.segment_min[7], 30.0);
  EXPECT_DOUBLE_EQ(s.segment_max[7], 36.0);
  EXPECT_DOUBLE_EQ(s.segment_mean[7], 32.0);  // (30 + 30 + 36) / 3
  EXPECT_DOUBLE_EQ(s.angle_rom[1], 0.0);
}

TEST(Measures, VisibilityCountsAndRate) {
  std::vector<FingerLabels> labels{{1, 0, -1, 1, 1}, {1, 1, -1, 0, 1}, {0, 1, -1, 0, 1}, {-1, -1, -1, -1, -1}};
  const VisibilityCounts v = visibility_table(2, labels);
  EXPECT_EQ(v.n_no_hand[0], 1);
  EXPECT_EQ(v.n_hidden[0], 1);
  EXPECT_EQ(v.n_visible[0], 2);
  EXPECT_NEAR(v.rate[0], 2.0 / 3.0, 1e-12);
  EXPECT_EQ(v.rate[2], -1.0);  // never saw the hand
  EXPECT_EQ(v.rate[3], 1.0 / 3.0);
}

TEST(Compare, LagFromWristCrossCorrelation) {
  HandTrack a(200), b(200);
  for (int f = 0; f < 200; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      a.at(f, i) = Vec3(50 * std::sin((f - 7) * 0.07), 10 * std::cos((f - 7) * 0.05), 0);
      b.at(f, i) = Vec3(50 * std::sin(f * 0.07), 10 * std::cos(f * 0.05), 0);
    }
  }
  const LagEstimate lag = estimate_lag(a, b, 30);
  ASSERT_TRUE(lag.valid);
  EXPECT_EQ(lag.lag_frames, 7);  // a trails b by 7 frames
  EXPECT_GT(lag.correlation, 0.99);
  EXPECT_TRUE(lag.clear);
  // The same shift searched only up to ±5 frames ends on the window's edge: not a clear lag.
  const LagEstimate edge = estimate_lag(a, b, 5);
  EXPECT_EQ(edge.lag_frames, 5);
  EXPECT_FALSE(edge.clear);
}

TEST(Compare, DifferencesAreLmcMinusVicon) {
  const HandTrack t = straight_hand(5);
  HandTrack v = t;
  for (int f = 0; f < 5; ++f) v.at(f, digit_point(0, 4)) += Vec3(0, 0, -2);  // Vicon thumb 2 mm longer
  const auto lm = measure_track(t), vm = measure_track(v);
  const Comparison c = compare_measures(lm, summarize(lm), vm, summarize(vm));
  EXPECT_EQ(c.frames, 5);
  EXPECT_NEAR(c.finger_diff_mean[0], -2.0, 1e-9);
  EXPECT_NEAR(c.finger_diff_sd[0], 0.0, 1e-9);
  EXPECT_NEAR(c.finger_mean_diff[0], -2.0, 1e-9);
  EXPECT_NEAR(c.finger_diff_mean[1], 0.0, 1e-9);
}

TEST(TrialTag, ParsesTheStudyScheme) {
  const TrialTag a = parse_trial_tag("Interp_LMC_Naiv_Static101.txt");
  EXPECT_TRUE(a.parsed);
  EXPECT_EQ(a.trial, "Naiv_Static101");
  EXPECT_EQ(a.layout, "initial");
  EXPECT_EQ(a.pose, "horizontal");
  EXPECT_EQ(a.motion, "static");
  EXPECT_EQ(a.repetition, 1);
  const TrialTag b = parse_trial_tag("LMC_Opti_Thumb205.raw.txt");
  EXPECT_EQ(b.trial, "Opti_Thumb205");
  EXPECT_EQ(b.layout, "optimized");
  EXPECT_EQ(b.pose, "vertical");
  EXPECT_EQ(b.motion, "thumb");
  EXPECT_EQ(b.repetition, 5);
  EXPECT_EQ(parse_trial_tag("Naiv_Trial102.trc").motion, "dynamic");
  const TrialTag c = parse_trial_tag("my_trial.txt");
  EXPECT_FALSE(c.parsed);
  EXPECT_EQ(c.layout, "unknown");
  EXPECT_EQ(trial_name_of("LMC_x.resampled.txt"), "x");
}

}  // namespace
}  // namespace lmc
