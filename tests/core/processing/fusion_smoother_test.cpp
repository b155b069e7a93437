#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "core/processing/fusion_lanes.h"
#include "core/processing/fusion_smoother.h"
#include "core/processing/kalman_reference.h"

namespace lmc {
namespace {

HandTrack moving(int frames, double bias, double noise, std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, noise);
  HandTrack t(frames);
  for (int f = 0; f < frames; ++f) {
    const double x = 30.0 * std::sin(f * 0.03);
    for (int i = 0; i < kNumHandPoints; ++i) t.at(f, i) = Vec3(x + bias + g(rng), 150.0 + g(rng), -i + g(rng));
  }
  return t;
}

double truth_x(int f) {
  return 30.0 * std::sin(f * 0.03);
}

TEST(FusionSmoother, DownweightsHiddenGuessesAndBeatsReference) {
  std::mt19937 rng(5);
  const int n = 300;
  HandTrack good = moving(n, 0.0, 1.0, rng);
  HandTrack guess = moving(n, 15.0, 1.0, rng);  // internal-model guess: biased by 15 mm
  std::vector<FingerLabels> good_labels(n, FingerLabels{1, 1, 1, 1, 1});
  std::vector<FingerLabels> guess_labels(n, FingerLabels{0, 0, 0, 0, 0});
  SmootherParams p;
  const auto q_good = sample_quality(HandTrack(n), good_labels, p);
  const auto q_guess = sample_quality(HandTrack(n), guess_labels, p);
  const HandTrack fused = fuse_default({&good, &guess}, {&q_good, &q_guess}, p);
  const HandTrack ref = fuse_reference({&good, &guess});
  double e_def = 0, e_ref = 0;
  for (int f = 30; f < n; ++f) {
    const int i = digit_point(1, 4);
    e_def += std::pow(fused.at(f, i).x() - truth_x(f), 2);
    e_ref += std::pow(ref.at(f, i).x() - truth_x(f), 2);
  }
  e_def = std::sqrt(e_def / (n - 30));
  e_ref = std::sqrt(e_ref / (n - 30));
  EXPECT_LT(e_def, 1.5);
  EXPECT_LT(e_def, 0.5 * e_ref);
}

TEST(FusionSmoother, HandlesNaNAnywhereAndLeavesLongGapsNaN) {
  std::mt19937 rng(9);
  const int n = 100;
  HandTrack a = moving(n, 0.0, 0.5, rng);
  HandTrack b = moving(n, 0.0, 0.5, rng);
  for (int f = 0; f < 10; ++f) a.at(f, 7) = Vec3::Constant(kNaN);                // a starts late
  for (int f = 40; f < 60; ++f) a.at(f, 7) = b.at(f, 7) = Vec3::Constant(kNaN);  // 20-frame hole in both
  for (int f = 70; f < 73; ++f) a.at(f, 7) = b.at(f, 7) = Vec3::Constant(kNaN);  // 3-frame hole: bridged
  b.at(90, 7).x() = kNaN;                                                        // a single coordinate
  const HandTrack fused = fuse_default({&a, &b}, {nullptr, nullptr});
  EXPECT_TRUE(is_finite(fused.at(0, 7)));
  for (int f = 40; f < 60; ++f) EXPECT_FALSE(std::isfinite(fused.at(f, 7).x())) << f;
  for (int f = 70; f < 73; ++f) EXPECT_NEAR(fused.at(f, 7).x(), truth_x(f), 1.5) << f;
  EXPECT_NEAR(fused.at(90, 7).x(), truth_x(90), 1.5);
  // Never measured → NaN; point 3 of an empty track stays NaN.
  HandTrack empty(10);
  const HandTrack none = fuse_default({&empty}, {nullptr});
  EXPECT_FALSE(none.has_hand(5));
}

// The y and z of a point measured as its x share the x lane's covariances and gains
// (fusion_smoother.cpp); when the y is measured otherwise (one sample missing), y and z run filters
// of their own. The z is measured the same in both cases, so its fused values must be the same bit
// for bit: the shared gains are exactly the ones its own filter computes.
TEST(FusionSmoother, ALaneSharingItsPointsGainsEqualsItsOwnFilterBitForBit) {
  std::mt19937 rng(21);
  const int n = 200;
  const HandTrack a = moving(n, 0.0, 0.8, rng);
  const HandTrack b = moving(n, 2.0, 0.8, rng);
  HandTrack b_gap = b;
  const int point = digit_point(2, kRebuiltFromJoint);  // fused as it is, not rebuilt from bone lengths
  b_gap.at(120, point).y() = kNaN;                      // y alone: the point's lanes no longer measured alike
  std::vector<FingerLabels> labels(n, FingerLabels{1, 1, 0, 1, 1});
  SmootherParams p;
  const auto qa = sample_quality(a, labels, p), qb = sample_quality(b, labels, p);
  const HandTrack shared = fuse_default({&a, &b}, {&qa, &qb}, p);
  const HandTrack own = fuse_default({&a, &b_gap}, {&qa, &qb}, p);
  int compared = 0;
  for (int f = 0; f < n; ++f) {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(shared.at(f, point).z()), std::bit_cast<std::uint64_t>(own.at(f, point).z()))
        << "frame " << f;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(shared.at(f, point).x()), std::bit_cast<std::uint64_t>(own.at(f, point).x()))
        << "frame " << f;
    compared += std::isfinite(shared.at(f, point).z()) ? 1 : 0;
  }
  EXPECT_EQ(compared, n);
  EXPECT_NE(shared.at(120, point).y(), own.at(120, point).y()) << "the y lane did see the missing sample";
}

TEST(FusionSmoother, AxisCutAndElbowGetLowerWeight) {
  HandTrack t(2);
  for (int i = 0; i < kNumHandPoints; ++i) t.at(0, i) = t.at(1, i) = Vec3(0, 100, 0);
  t.at(1, 9) = Vec3(0, 250.0, 10);
  SmootherParams p;
  const auto q = sample_quality(t, {}, p);
  EXPECT_FLOAT_EQ(q[static_cast<size_t>(kNumHandPoints) + 9], static_cast<float>(p.axis_cut_factor));
  EXPECT_FLOAT_EQ(q[9], 1.0f);
  EXPECT_FLOAT_EQ(q[kElbow], static_cast<float>(p.elbow_factor));
}

}  // namespace
}  // namespace lmc
