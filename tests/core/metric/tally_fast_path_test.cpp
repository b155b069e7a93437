// The search's fast paths against the plain ones they replace (issue #15 speed-up): the kernel's
// axis-cut bits against seen_marker_beyond_cut, the tally built from them against the tally built
// frame by frame with the reference tests, and the byte-wise worst-finger count against counting.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/hand/pose_set_generator.h"
#include "core/layout/layout.h"
#include "core/metric/coverage.h"
#include "core/metric/layout_tally.h"
#include "core/visibility/visibility_explain.h"
#include "core/visibility/visibility_kernel.h"
#include "tests/support/mc_frames.h"

namespace lmc {
namespace tally_fast_path_test {

const std::vector<PreparedFrame>& some_frames() { return test::mc_frames(300, 7); }

// Devices on and around the table, most of them seeing the hand.
std::vector<DeviceView> random_views(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<DeviceView> v;
  for (int i = 0; i < count; ++i) {
    DevicePose p;
    p.x_mm = 300 * u(rng);
    p.y_mm = 40 * u(rng);
    p.z_mm = 300 * u(rng);
    p.rx_deg = 50 * u(rng);
    p.ry_deg = 180 * u(rng);
    p.rz_deg = 10 * u(rng);
    v.push_back(DeviceView::from_pose(p));
  }
  return v;
}

TEST(TallyFastPath, KernelCutBitsAreTheSeenMarkerCutAndEveryBuildAgrees) {
  const auto& frames = some_frames();
  const VisibilityLimits lim = make_limits({});
  int seeing = 0, cut = 0;
  for (const DeviceView& d : random_views(40, 3)) {
    for (double cut_mm : {kAxisCutMm, 150.0}) {
      std::vector<FingerBits> bits(frames.size()), cuts(frames.size()), bits0(frames.size()), cuts0(frames.size()),
          plain(frames.size());
      device_visibility_with_cut(d, frames, lim, cut_mm, bits, cuts);
      device_visibility(d, frames, lim, plain);
      EXPECT_EQ(bits, plain);
      // Every build of the kernel this CPU runs gives the same bits (visibility_kernel.h).
      for (const KernelBuild build : {KernelBuild::kAvx512, KernelBuild::kAvx2, KernelBuild::kBaseline}) {
        device_visibility_with_cut(d, frames, lim, cut_mm, bits0, cuts0, build);
        EXPECT_EQ(bits, bits0) << kernel_build_name(build);
        EXPECT_EQ(cuts, cuts0) << kernel_build_name(build);
        device_visibility(d, frames, lim, plain, build);
        EXPECT_EQ(bits, plain) << kernel_build_name(build);
      }
      for (size_t j = 0; j < frames.size(); ++j) {
        ASSERT_EQ(bits[j], explain_visibility(frames[j], d, lim).bits);
        if (bits[j] == 0) continue;
        ++seeing;
        for (int f = 0; f < kNumDigits; ++f) {
          const auto one = static_cast<FingerBits>(1u << f);
          ASSERT_EQ((cuts[j] & one) != 0, seen_marker_beyond_cut(frames[j], d, one, cut_mm)) << j << " " << f;
        }
        if ((bits[j] & cuts[j]) != 0) ++cut;
      }
    }
  }
  EXPECT_GT(seeing, 2000);
  EXPECT_GT(cut, 200);
}

void expect_same(const LayoutTally& a, const LayoutTally& b) {
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_EQ(a.c, b.c);
  EXPECT_EQ(a.c_inside_cut, b.c_inside_cut);
  EXPECT_EQ(a.device_seeing_frames, b.device_seeing_frames);
  EXPECT_EQ(a.device_sole_frames, b.device_sole_frames);
  EXPECT_EQ(a.device_cut_frames, b.device_cut_frames);
  EXPECT_EQ(a.device_off_centre, b.device_off_centre);
}

TEST(TallyFastPath, TallyFromKernelCutBitsEqualsTheFrameByFrameTally) {
  const auto& frames = some_frames();
  const VisibilityLimits lim = make_limits({});
  std::vector<int> subset;
  for (int j = 0; j < static_cast<int>(frames.size()); j += 3) subset.push_back(j);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto views = random_views(4, seed);
    LayoutTally all(4), some(4);
    for (size_t j = 0; j < frames.size(); ++j) {
      FingerBits bits[4];
      for (size_t d = 0; d < 4; ++d) bits[d] = explain_visibility(frames[j], views[d], lim).bits;
      tally_frame(frames[j], views, bits, lim, kAxisCutMm, all);
      if (j % 3 == 0) tally_frame(frames[j], views, bits, lim, kAxisCutMm, some);
    }
    expect_same(tally_layout(views, frames, lim), all);
    expect_same(tally_layout(views, frames, lim, kAxisCutMm, subset), some);
  }
}

TEST(TallyFastPath, WorstFingerCountMatchesCountingFingerByFinger) {
  std::mt19937_64 rng(5);
  for (int i = 0; i < 20000; ++i) {
    const int devices = 1 + static_cast<int>(rng() % kMaxDevices);
    FingerBits bits[kMaxDevices];
    for (int d = 0; d < devices; ++d) bits[d] = static_cast<FingerBits>(rng() & 0x1F);
    int counts[kNumDigits] = {};
    for (int d = 0; d < devices; ++d) {
      for (int k = 0; k < kNumDigits; ++k) counts[k] += (bits[d] >> k) & 1;
    }
    const int expected = *std::min_element(counts, counts + kNumDigits);
    ASSERT_EQ(worst_finger_count(bits, devices), expected);
  }
}

}  // namespace tally_fast_path_test
}  // namespace lmc
