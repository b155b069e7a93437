// The simulator's study-errors model does what its configuration says: bone
// scales, joint offsets, per-controller draws, the preset switch, and nothing at all when off.
#include <cmath>
#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "devices/sim/controller_hand_model.h"
#include "devices/sim/sim_config.h"
#include "devices/sim/sim_rig.h"
#include "tests/devices/sim/sim_fixtures.h"
#include "tests/support/reference_data.h"

namespace lmc::devices {
namespace sim_study_errors_test {

using sim_fixtures::exact;
using sim_fixtures::paper_initial;
using sim_fixtures::trial_hash;

double bone(const HandFrame& f, int digit, int b) {
  return (f.point(digit_point(digit, b + 1)) - f.point(digit_point(digit, b))).norm();
}

// Every present device frame of the first `events` events, realigned to the world, with its truth.
template <typename Fn>
int for_each_realigned(const Layout& layout, const SimConfig& c, int events, Fn fn) {
  SimRig rig(layout, c);
  int n = 0;
  for (int i = 0; i < events; ++i) {
    const SimEvent e = rig.next();
    if (!e.is_frame || !e.frame.frame.hand_present) continue;
    const LayoutDevice& ld = layout.devices[static_cast<size_t>(e.frame.frame.device_id - 1)];
    HandFrame world = e.frame.frame;
    for (int p = 0; p < kNumHandPoints; ++p)
      world.point(p) = (p == kPalmNormal || p == kPalmDirection) ? Vec3(ld.pose.rotation() * world.point(p))
                                                                 : ld.to_world(world.point(p));
    fn(world, rig.truth_at(e.time_s), e.frame.frame.device_id);
    ++n;
  }
  return n;
}

TEST(SimStudyErrors, ScaleOnOneBoneMakesThatBoneScaleTimesTheTruthAndLeavesTheRest) {
  SimConfig c = exact();
  c.hand_model_error.enabled = true;
  c.hand_model_error.segment_scale[1][2] = 0.8;  // index Inter→Dist
  c.hand_model_error.segment_scale[4][1] = 0.7;  // pinky Proxi→Inter
  const int n = for_each_realigned(paper_initial(), c, 200, [](const HandFrame& dev, const HandFrame& truth, int) {
    for (int dg = 0; dg < kNumDigits; ++dg)
      for (int b = 0; b < 4; ++b) {
        const double s = (dg == 1 && b == 2) ? 0.8 : (dg == 4 && b == 1) ? 0.7 : 1.0;
        EXPECT_NEAR(bone(dev, dg, b), s * bone(truth, dg, b), 1e-9) << dg << "/" << b;
      }
    // The chain is rebuilt from the Meta point, in the direction of the true bones.
    for (int dg = 0; dg < kNumDigits; ++dg)
      EXPECT_LT((dev.point(digit_point(dg, 0)) - truth.point(digit_point(dg, 0))).norm(), 1e-9);
    EXPECT_LT((dev.point(kPalm) - truth.point(kPalm)).norm(), 1e-9);
    EXPECT_LT((dev.point(kWrist) - truth.point(kWrist)).norm(), 1e-9);
  });
  EXPECT_GT(n, 20);
}

TEST(SimStudyErrors, JointOffsetMovesTheJointTowardsThePalmSideOfItsBone) {
  SimConfig c = exact();
  c.hand_model_error.enabled = true;
  c.hand_model_error.joint_offset_mm = {0, 0, 6, 0, 0};  // Inter only
  const int n = for_each_realigned(paper_initial(), c, 200, [](const HandFrame& dev, const HandFrame& truth, int) {
    const Vec3 normal = truth.point(kPalmNormal);
    for (int dg = 1; dg < kNumDigits; ++dg) {
      const Vec3 moved = dev.point(digit_point(dg, 2)) - truth.point(digit_point(dg, 2));
      EXPECT_NEAR(moved.norm(), 6.0, 1e-9) << dg;
      EXPECT_GT(moved.dot(normal), 0.0) << dg;  // the palm side, where the palm normal points
      const Vec3 along = (truth.point(digit_point(dg, 3)) - truth.point(digit_point(dg, 1))).normalized();
      EXPECT_NEAR(moved.normalized().dot(along), 0.0, 0.2) << dg;  // across the bone, not along it
      for (int j : {0, 1, 3, 4})
        EXPECT_LT((dev.point(digit_point(dg, j)) - truth.point(digit_point(dg, j))).norm(), 1e-9);
    }
  });
  EXPECT_GT(n, 20);
}

TEST(SimStudyErrors, ThumbMetaStaysOnProxiWhenItsJointsMove) {
  HandModelError e;
  e.enabled = true;
  e.joint_offset_mm = {0, 9, 9, 9, 9};
  SimConfig c = exact();
  c.hand_model_error = e;
  for_each_realigned(paper_initial(), c, 100, [](const HandFrame& dev, const HandFrame& truth, int) {
    ASSERT_LT((truth.point(Digit::kThumb, Joint::kMeta) - truth.point(Digit::kThumb, Joint::kProxi)).norm(), 1e-9);
    EXPECT_LT((dev.point(Digit::kThumb, Joint::kMeta) - dev.point(Digit::kThumb, Joint::kProxi)).norm(), 1e-9);
  });
}

TEST(SimStudyErrors, EachControllerDrawsItsOwnModelAndKeepsItAcrossTrials) {
  HandModelError e;
  e.enabled = true;
  e.scale_spread = 0.05;
  e.joint_offset_spread_mm = 2;
  const ControllerHandModel a = draw_controller_hand_model(e, 11);
  const ControllerHandModel a2 = draw_controller_hand_model(e, 11);
  const ControllerHandModel b = draw_controller_hand_model(e, 12);
  EXPECT_EQ(a.scale, a2.scale);
  EXPECT_NE(a.scale, b.scale);
  // One factor per digit: all of a digit's bones get it.
  for (size_t dg = 0; dg < kNumDigits; ++dg)
    for (size_t bn = 1; bn < 4; ++bn) EXPECT_DOUBLE_EQ(a.scale[dg][bn], a.scale[dg][0]);

  // Same calibration seed, other trial seed: the controllers' fingers are as long as before.
  SimConfig c = exact();
  c.hand_model_error = e;
  c.calibration_seed = 5;
  auto index_length = [](const SimConfig& cfg) {
    std::map<int, double> by_device;
    for_each_realigned(paper_initial(), cfg, 100, [&](const HandFrame& dev, const HandFrame& truth, int id) {
      by_device[id] = (bone(dev, 1, 1) + bone(dev, 1, 2) + bone(dev, 1, 3)) /
                      (bone(truth, 1, 1) + bone(truth, 1, 2) + bone(truth, 1, 3));
    });
    return by_device;
  };
  c.seed = 1;
  const auto first = index_length(c);
  c.seed = 2;
  const auto second = index_length(c);
  ASSERT_GE(first.size(), 2u);
  for (const auto& [id, ratio] : first) {
    ASSERT_TRUE(second.contains(id));
    EXPECT_NEAR(second.at(id), ratio, 1e-6) << id;
  }
  EXPECT_NE(first.begin()->second, std::next(first.begin())->second);
}

TEST(SimStudyErrors, PalmSideTurnsWithTheBoneAlsoInAFistPast90Degrees) {
  // Palm down: direction +x, normal −y (the palm side), so flexion turns a bone from +x to −y to −x.
  HandFrame f;
  f.points.fill(Vec3::Zero());
  f.point(kPalmDirection) = Vec3(1, 0, 0);
  f.point(kPalmNormal) = Vec3(0, -1, 0);
  const double kDeg = 3.14159265358979323846 / 180.0;
  const double flexion[4] = {0, 60, 120, 150};  // direction of each index bone from the palm's
  Vec3 p(0, 0, 0);
  for (int b = 0; b < 4; ++b) {
    f.point(digit_point(1, b)) = p;
    p += 30.0 * Vec3(std::cos(flexion[b] * kDeg), -std::sin(flexion[b] * kDeg), 0);
  }
  f.point(digit_point(1, 4)) = p;
  ControllerHandModel m = draw_controller_hand_model(HandModelError{}, 1);
  m.offset_local[1][4] = Vec3(0, 5, 0);  // fingertip, 5 mm to the palm side of the last bone
  HandFrame out = f;
  apply_controller_hand_model(m, out);
  // The palm side of a bone turned by θ is −y turned by θ: (−sin θ, −cos θ), here up and back.
  const Vec3 expected = 5.0 * Vec3(-std::sin(150 * kDeg), -std::cos(150 * kDeg), 0);
  EXPECT_LT((out.point(digit_point(1, 4)) - f.point(digit_point(1, 4)) - expected).norm(), 1e-9);
}

TEST(SimStudyErrors, OffChangesNothingByteForByte) {
  const Layout layout = paper_initial();
  SimConfig c;
  c.seed = 4;
  apply_motion_spec(c, "horizontal/index");
  const std::uint64_t today = trial_hash(generate_sim_trial(layout, c, 1.0));
  // The hash of the simulator before the model existed (same seed, layout, motion, 1 s); `lmc
  // record --fast --seed 4 --motion horizontal/index` also wrote identical raw files then and now.
  EXPECT_EQ(today, 0x5af72a55b1cd603aULL);
  // Values set but the switch off: still nothing.
  SimConfig off = c;
  off.hand_model_error = study_errors_hand_model();
  off.hand_model_error.enabled = false;
  EXPECT_EQ(trial_hash(generate_sim_trial(layout, off, 1.0)), today);
  const SimConfig from_json =
      sim_config_from_json(nlohmann::json{{"seed", 4}, {"motion", "horizontal/index"}, {"study_errors", false}}, "mem");
  EXPECT_EQ(trial_hash(generate_sim_trial(layout, from_json, 1.0)), today);
  EXPECT_FALSE(sim_config_to_json(c).contains("hand_model_error"));
}

TEST(SimStudyErrors, PresetSwitchSetsTheFittedValuesAndKeysBesideItOverrideThem) {
  const SimConfig c = sim_config_from_json(nlohmann::json{{"study_errors", true}}, "mem");
  EXPECT_TRUE(c.study_errors);
  EXPECT_TRUE(c.hand_model_error.enabled);
  EXPECT_EQ(c.hand_model_error.segment_scale, study_errors_hand_model().segment_scale);
  EXPECT_EQ(c.calibration_random_translation_mm, kStudyCalibrationTranslationMm);
  EXPECT_EQ(c.calibration_random_rotation_deg, kStudyCalibrationRotationDeg);
  EXPECT_TRUE(c.axis_cut);
  EXPECT_TRUE(c.elbow_error);

  const SimConfig o =
      sim_config_from_json(nlohmann::json::parse(R"({"study_errors": true, "calibration_random_rotation_deg": 0,
                                "hand_model_error": {"scale_spread": 0, "segment_scale": {"ring": [1, 0.5, 0.5, 0.5]}}})"),
                           "mem");
  EXPECT_EQ(o.calibration_random_rotation_deg, 0.0);
  EXPECT_EQ(o.hand_model_error.scale_spread, 0.0);
  EXPECT_EQ(o.hand_model_error.segment_scale[3][1], 0.5);
  EXPECT_EQ(o.hand_model_error.segment_scale[1], study_errors_hand_model().segment_scale[1]);

  const SimConfig back = sim_config_from_json(sim_config_to_json(o), "mem");
  EXPECT_EQ(back.hand_model_error.segment_scale, o.hand_model_error.segment_scale);
  EXPECT_EQ(back.hand_model_error.joint_offset_mm, o.hand_model_error.joint_offset_mm);
  EXPECT_EQ(back.calibration_random_rotation_deg, 0.0);

  EXPECT_THROW(sim_config_from_json(nlohmann::json::parse(R"({"hand_model_error": {"scale": 1}})"), "m"), Error);
  EXPECT_THROW(
      sim_config_from_json(nlohmann::json::parse(R"({"hand_model_error": {"segment_scale": {"index": [1, 0]}}})"), "m"),
      Error);
}

}  // namespace sim_study_errors_test
}  // namespace lmc::devices
