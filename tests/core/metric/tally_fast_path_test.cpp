// The search's fast paths against the plain ones they replace: the kernel's
// axis-cut bits against seen_marker_beyond_cut, the tally built from them against the tally built
// frame by frame with the reference tests, the tally of a run of frames against counting each
// frame finger by finger, and the byte-wise worst-finger count against counting.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/common/error.h"
#include "core/hand/pose_set_generator.h"
#include "core/layout/layout.h"
#include "core/metric/coverage.h"
#include "core/metric/inside_cut_visibility.h"
#include "core/metric/layout_tally.h"
#include "core/optimise/search_space.h"
#include "core/visibility/visibility_explain.h"
#include "core/visibility/visibility_kernel.h"
#include "tests/support/mc_frames.h"

namespace lmc {
namespace tally_fast_path_test {

const std::vector<PreparedFrame>& some_frames() {
  return test::mc_frames(300, 7);
}

// Device poses on and around the table, most of them seeing the hand.
std::vector<DevicePose> random_poses(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<DevicePose> v;
  for (int i = 0; i < count; ++i) {
    DevicePose p;
    p.x_mm = 300 * u(rng);
    p.y_mm = 40 * u(rng);
    p.z_mm = 300 * u(rng);
    p.rx_deg = 50 * u(rng);
    p.ry_deg = 180 * u(rng);
    p.rz_deg = 10 * u(rng);
    v.push_back(p);
  }
  return v;
}

// Frames first, first + step, … of the test's frames (a pose-set subset, as the report's horizontal
// and vertical poses are).
std::vector<int> every_nth_frame(int first, int step) {
  std::vector<int> subset;
  for (int j = first; j < static_cast<int>(some_frames().size()); j += step) subset.push_back(j);
  return subset;
}

std::vector<DeviceView> random_views(int count, std::uint64_t seed) {
  std::vector<DeviceView> v;
  for (const DevicePose& p : random_poses(count, seed)) v.push_back(DeviceView::from_pose(p));
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
  const std::vector<int> subset = every_nth_frame(0, 3);
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

// What tally_frames must add, counted the plain way: per frame, finger by finger and device by
// device (the definitions in layout_tally.h).
LayoutTally count_plainly(std::span<const PreparedFrame> frames, std::span<const DeviceView> views,
                          const std::vector<std::vector<FingerBits>>& bits,
                          const std::vector<std::vector<FingerBits>>& cut, const VisibilityLimits& lim) {
  const auto nd = static_cast<int>(views.size());
  LayoutTally t(nd);
  for (size_t j = 0; j < frames.size(); ++j) {
    ++t.frames;
    int worst = nd, worst_inside = nd;
    FingerBits sole = 0;
    for (int f = 0; f < kNumDigits; ++f) {
      int seeing = 0, seeing_inside = 0;
      for (int d = 0; d < nd; ++d) {
        const bool seen = (bits[static_cast<size_t>(d)][j] >> f) & 1;
        const bool beyond = (cut[static_cast<size_t>(d)][j] >> f) & 1;
        seeing += seen;
        seeing_inside += seen && !beyond;
      }
      worst = std::min(worst, seeing);
      worst_inside = std::min(worst_inside, seeing_inside);
      if (seeing == 1) sole = static_cast<FingerBits>(sole | (1u << f));
    }
    ++t.c[static_cast<size_t>(worst)];
    ++t.c_inside_cut[static_cast<size_t>(worst_inside)];
    for (int d = 0; d < nd; ++d) {
      const auto dd = static_cast<size_t>(d);
      const FingerBits b = bits[dd][j];
      if (b == 0) continue;
      ++t.device_seeing_frames[dd];
      if ((b & sole) != 0) ++t.device_sole_frames[dd];
      if ((b & cut[dd][j]) != 0) ++t.device_cut_frames[dd];
      t.device_off_centre[dd] += std::llround(off_centre_penalty(frames[j], views[dd], lim) * kOffCentreScale);
    }
  }
  return t;
}

TEST(TallyFastPath, TallyOfARunOfFramesEqualsCountingEachFrame) {
  const auto& frames = some_frames();
  const VisibilityLimits lim = make_limits({});
  std::mt19937_64 rng(11);
  // Runs shorter than, equal to and longer than the 64-frame blocks, 1 to 8 devices, random bits
  // (any finger seen or cut, also bits of unseen fingers set in the cut, as the kernel leaves them).
  for (const size_t count : {size_t{1}, size_t{5}, size_t{63}, size_t{64}, size_t{65}, size_t{200}, frames.size()}) {
    for (int nd = 1; nd <= kMaxDevices; ++nd) {
      const auto views = random_views(nd, rng());
      const size_t stride = count + 3;  // the columns need not be packed
      std::vector<FingerBits> flat_bits(static_cast<size_t>(nd) * stride), flat_cut(flat_bits.size());
      std::vector<std::vector<FingerBits>> bits(static_cast<size_t>(nd)), cut(static_cast<size_t>(nd));
      for (size_t d = 0; d < static_cast<size_t>(nd); ++d) {
        for (size_t j = 0; j < count; ++j) {
          // A third of the pairs see nothing, as devices beside the hand do.
          const auto b = static_cast<FingerBits>(rng() % 3 == 0 ? 0 : rng() & 0x1F);
          const auto c = static_cast<FingerBits>(rng() % 4 == 0 ? rng() & 0x1F : 0);
          flat_bits[d * stride + j] = b;
          flat_cut[d * stride + j] = c;
          bits[d].push_back(b);
          cut[d].push_back(c);
        }
      }
      const std::span<const PreparedFrame> run(frames.data(), count);
      LayoutTally t(nd);
      tally_frames(run, views, flat_bits.data(), flat_cut.data(), stride, lim, t);
      SCOPED_TRACE(testing::Message() << count << " frames, " << nd << " devices");
      const LayoutTally expected = count_plainly(run, views, bits, cut, lim);
      expect_same(t, expected);
      EXPECT_GT(expected.seeing_pairs(), 0);
    }
  }
  LayoutTally t(9);
  FingerBits nine[9] = {};
  EXPECT_THROW(
      tally_frames(std::span<const PreparedFrame>(frames.data(), 1), random_views(9, 1), nine, nine, 1, lim, t), Error);
}

// The layout report counts its tallies from the tables it already has (no second kernel pass):
// the same tally as running the kernel again, over all frames and over a subset.
TEST(TallyFastPath, TallyFromTheVisibilityTablesEqualsTallyingTheLayout) {
  const auto& frames = some_frames();
  const VisibilityLimits lim = make_limits({});
  const std::vector<int> subset = every_nth_frame(1, 4);
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    // The devices random_views places, as a layout (visibility_with_inside_cut takes one).
    Layout layout = default_start_layout(4);
    const std::vector<DevicePose> poses = random_poses(4, seed);
    for (size_t d = 0; d < 4; ++d) layout.devices[d].pose = poses[d];
    std::vector<DeviceView> layout_views;
    for (const auto& dev : layout.devices) layout_views.push_back(DeviceView::from_device(dev));
    const VisibilityWithCut tables = visibility_with_inside_cut(layout, frames);
    const VisibilityLimits limits = make_limits(VisibilityParams::from_sensor(common_sensor(layout)));
    const LayoutTally all = tally_from_visibility(tables, layout_views, frames, limits);
    expect_same(all, tally_layout(layout_views, frames, limits));
    expect_same(tally_from_visibility(tables, layout_views, frames, limits, subset),
                tally_layout(layout_views, frames, limits, kAxisCutMm, subset));
    EXPECT_GT(all.cut_pairs(), 0);
  }
  const Layout two = default_start_layout(2);
  const VisibilityWithCut tables = visibility_with_inside_cut(two, frames);
  EXPECT_THROW(tally_from_visibility(tables, random_views(3, 1), frames, lim), Error);
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
