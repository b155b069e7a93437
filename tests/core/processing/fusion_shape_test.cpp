// The default fusion keeps the hand's shape, on constructed hands: controllers
// with known finger lengths and a known misalignment between their realigned frames. The fused
// finger length must stay within ±2 mm of the controllers' median and no fused segment may be
// shorter than the shortest controller's, whatever the per-point weights.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/common/angles.h"
#include "core/hand/hand_model.h"
#include "core/hand/reference_poses.h"
#include "core/processing/consensus.h"
#include "core/processing/fusion_lanes.h"
#include "core/processing/fusion_smoother.h"

namespace fusion_shape_test {

using namespace lmc;

// The reference open hand as one controller reports it: every digit's bones from the MCP joint
// outward scaled by `scale` (the controller's own hand model), then the whole hand turned by
// `turn_deg` about the vertical through the palm and shifted by `shift` (residual misalignment of
// its realigned frame).
HandTrack controller_hand(int frames, double scale, double turn_deg, const Vec3& shift) {
  const HandModel model;
  HandFrame h = reference_pose(model, HandOrientation::kHorizontal, HandMotion::kOpen);
  for (int dg = 0; dg < kNumDigits; ++dg) {
    const Vec3 mcp = h.point(digit_point(dg, 1));
    for (int j = 2; j < kJointsPerDigit; ++j)
      h.point(digit_point(dg, j)) = mcp + scale * (h.point(digit_point(dg, j)) - mcp);
  }
  const Eigen::Matrix3d r = Eigen::AngleAxisd(turn_deg * kRadPerDeg, Vec3::UnitY()).toRotationMatrix();
  const Vec3 palm = h.point(kPalm);
  HandTrack t(frames);
  for (int f = 0; f < frames; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      const bool vector = i == kPalmNormal || i == kPalmDirection;
      t.at(f, i) = vector ? Vec3(r * h.point(i)) : Vec3(palm + r * (h.point(i) - palm) + shift);
    }
  }
  return t;
}

std::vector<std::vector<FingerLabels>> every_finger_seen(int devices, int frames) {
  FingerLabels seen{};
  seen.fill(1);
  return std::vector<std::vector<FingerLabels>>(static_cast<size_t>(devices),
                                                std::vector<FingerLabels>(static_cast<size_t>(frames), seen));
}

struct Rig {
  std::vector<DeviceTrack> devices;
  std::vector<std::vector<float>> quality;  // per device, per (frame, point); filled with 1
};

Rig three_misaligned_controllers(int frames) {
  Rig rig;
  // Hand models 8 % short, true and 8 % long; frames turned ±20° and shifted up to 9 mm apart.
  rig.devices.push_back({1, controller_hand(frames, 0.92, -20.0, Vec3(-4, 2, 3))});
  rig.devices.push_back({2, controller_hand(frames, 1.00, 0.0, Vec3(0, 0, 0))});
  rig.devices.push_back({3, controller_hand(frames, 1.08, 20.0, Vec3(5, -3, -2))});
  rig.quality.assign(3, std::vector<float>(static_cast<size_t>(frames) * kNumHandPoints, 1.0f));
  return rig;
}

ConsensusReport fuse_and_judge(const Rig& rig, int frames, HandTrack* fused_out = nullptr) {
  std::vector<const HandTrack*> tracks;
  std::vector<const std::vector<float>*> q;
  for (size_t d = 0; d < rig.devices.size(); ++d) {
    tracks.push_back(&rig.devices[d].track);
    q.push_back(&rig.quality[d]);
  }
  const HandTrack fused = fuse_default(tracks, q);
  if (fused_out != nullptr) *fused_out = fused;
  return consensus_report(rig.devices, every_finger_seen(static_cast<int>(rig.devices.size()), frames), fused);
}

void expect_shape_kept(const ConsensusReport& r, const std::string& what) {
  for (int f = 0; f < kNumFingers; ++f) {
    const FingerConsensus& fc = r.fingers[static_cast<size_t>(f)];
    EXPECT_NEAR(fc.finger.fused_minus_median(), 0.0, 2.0) << what << ", finger " << f;
    for (size_t s = 0; s < fc.segment.size(); ++s) {
      EXPECT_GE(fc.segment[s].fused, fc.segment[s].shortest - 1e-6) << what << ", finger " << f << " segment " << s;
      EXPECT_LE(fc.segment[s].fused, fc.segment[s].longest + 1e-6) << what << ", finger " << f << " segment " << s;
    }
  }
}

TEST(FusionShape, MisalignedControllersKeepTheMedianFingerLength) {
  const int n = 40;
  const Rig rig = three_misaligned_controllers(n);
  const ConsensusReport r = fuse_and_judge(rig, n);
  expect_shape_kept(r, "equal weights");
  // The construction does misalign them: fused points sit millimetres from each controller's.
  EXPECT_GT(r.fingers[2].point_distance_mm, 3.0);
}

TEST(FusionShape, WeightsThatDifferBetweenTheJointsOfAFingerDoNotShortenIt) {
  // Every point of every controller gets its own weight (1 or 400, as an axis cut or a hidden
  // finger gives): a point-by-point average would stitch each finger from different controllers.
  const int n = 40;
  Rig rig = three_misaligned_controllers(n);
  std::mt19937 rng(7);
  std::bernoulli_distribution cut(0.4);
  for (auto& q : rig.quality) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      const float factor = cut(rng) ? 400.0f : 1.0f;
      for (int f = 0; f < n; ++f) q[static_cast<size_t>(f) * kNumHandPoints + static_cast<size_t>(i)] = factor;
    }
  }
  const ConsensusReport r = fuse_and_judge(rig, n);
  for (int f = 0; f < kNumFingers; ++f) {
    const FingerConsensus& fc = r.fingers[static_cast<size_t>(f)];
    for (size_t s = 0; s < fc.segment.size(); ++s) {
      EXPECT_GE(fc.segment[s].fused, fc.segment[s].shortest - 1e-6) << "finger " << f << " segment " << s;
      EXPECT_LE(fc.segment[s].fused, fc.segment[s].longest + 1e-6) << "finger " << f << " segment " << s;
    }
  }
}

TEST(FusionShape, AFingerCutAtOneJointIsDownWeightedAsAWhole) {
  // Device-frame hand with the index Inter joint at the 250 mm cut on y: the whole index shares
  // its weight, the other fingers keep theirs; a coordinate well beyond the cut was not cut.
  std::array<Vec3, kNumHandPoints> v;
  v.fill(Vec3(10, 180, -20));
  v[static_cast<size_t>(digit_point(1, 2))] = Vec3(10, 250.0, -20);
  v[static_cast<size_t>(digit_point(3, 4))] = Vec3(10, 268.0, -20);
  const SmootherParams p;
  std::array<float, kNumHandPoints> q{};
  frame_quality(v, nullptr, p, q);
  for (int j = 0; j < kJointsPerDigit; ++j) {
    EXPECT_FLOAT_EQ(q[static_cast<size_t>(digit_point(1, j))], static_cast<float>(p.axis_cut_factor)) << j;
    EXPECT_FLOAT_EQ(q[static_cast<size_t>(digit_point(2, j))], 1.0f) << j;
    EXPECT_FLOAT_EQ(q[static_cast<size_t>(digit_point(3, j))], 1.0f) << j;
  }
  EXPECT_FLOAT_EQ(q[kPalm], 1.0f);
}

TEST(FusionShape, LanesGiveBackOneControllersHand) {
  const HandTrack t = controller_hand(1, 1.0, 20.0, Vec3(3, 4, 5));
  std::array<float, kNumHandPoints> ones;
  ones.fill(1.0f);
  std::array<double, kFusionLanes> value{}, var{};
  hand_to_lanes(std::span<const Vec3, kNumHandPoints>(t.points.data(), kNumHandPoints), ones, 2.25, value, var);
  std::array<Vec3, kNumHandPoints> back;
  lanes_to_hand(value, back);
  for (int i = 0; i < kNumHandPoints; ++i) EXPECT_LT((back[static_cast<size_t>(i)] - t.at(0, i)).norm(), 1e-9) << i;
  // A NaN length makes the joints beyond it NaN, not the ones before.
  value[static_cast<size_t>(kFirstLengthLane + kRebuiltBonesPerDigit * 2 + 1)] = kNaN;  // middle Inter→Dist
  lanes_to_hand(value, back);
  EXPECT_TRUE(is_finite(back[static_cast<size_t>(digit_point(2, 2))]));
  EXPECT_FALSE(is_finite(back[static_cast<size_t>(digit_point(2, 3))]));
  EXPECT_FALSE(is_finite(back[static_cast<size_t>(digit_point(2, 4))]));
}

}  // namespace fusion_shape_test
