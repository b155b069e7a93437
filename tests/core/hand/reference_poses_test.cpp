#include "core/hand/reference_poses.h"

#include <gtest/gtest.h>

#include "core/io/layout_json.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_explain.h"
#include "core/visibility/visibility_kernel.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace {

TEST(ReferencePoses, PalmSits150mmAboveTheTableCentre) {
  const HandModel model;
  for (int i = 0; i < kNumReferencePoses; ++i) {
    const HandFrame f = reference_pose(model, static_cast<HandOrientation>(i / kNumHandMotions),
                                       static_cast<HandMotion>(i % kNumHandMotions));
    EXPECT_NEAR(f.point(kPalm).x(), 0.0, 1e-9);
    EXPECT_NEAR(f.point(kPalm).y(), 150.0, 1e-9);
    EXPECT_NEAR(f.point(kPalm).z(), 0.0, 1e-9);
    // Even the fully flexed wrist keeps every marker above the table.
    for (int k = 0; k < kNumHandPoints; ++k) {
      if (k == kPalmNormal || k == kPalmDirection) continue;  // unit vectors
      EXPECT_GT(f.point(k).y(), 10.0) << hand_point_name(k) << " pose " << i;
    }
  }
}

TEST(ReferencePoses, VerticalPalmFacesLeftThumbUp) {
  const HandModel model;
  const HandFrame h = reference_pose(model, HandOrientation::kHorizontal, HandMotion::kOpen);
  const HandFrame v = reference_pose(model, HandOrientation::kVertical, HandMotion::kOpen);
  EXPECT_NEAR(h.point(kPalmNormal).y(), -1.0, 1e-12);
  EXPECT_NEAR(v.point(kPalmNormal).x(), -1.0, 1e-12);
  EXPECT_GT(v.point(digit_point(0, 4)).y(), v.point(digit_point(4, 4)).y() + 40);  // thumb above pinky
  EXPECT_GT(v.point(kElbow).z(), 200);
}

TEST(ReferencePoses, MotionsReachTheirRanges) {
  const HandJointAngles idx = motion_angles(HandMotion::kIndexFlexion, 1.0);
  EXPECT_EQ(idx.finger(Digit::kIndex).pip_flexion_deg, 100.0);
  EXPECT_EQ(motion_angles(HandMotion::kIndexFlexion, 0.5).finger(Digit::kIndex).mcp_flexion_deg, 45.0);
  EXPECT_EQ(motion_angles(HandMotion::kWristExtension, 1.0).wrist_flexion_deg, -70.0);
  EXPECT_EQ(motion_angles(HandMotion::kOpen, 1.0), HandJointAngles{});
  EXPECT_EQ(pose_label_name(HandOrientation::kVertical, HandMotion::kThumbFlexion), "vertical/thumb");
  EXPECT_EQ(motion_from_name("wrist-extension"), HandMotion::kWristExtension);
  EXPECT_EQ(orientation_from_name("sideways"), std::nullopt);
}

// The hand enters every device from the user's side (a·f ≥ 0 for a device at rest) and the
// paper's layouts see the open hand: every finger is seen by at least one device — except the
// initial layout with the vertical hand, which the paper reports fails ("This policy is not
// satisfied in the initial configuration when doing vertical pose"): there the fingers stack
// above each other and the middle finger hides behind the ring finger from every device. Every
// device of the initial layout (right under the hand) has the hand in range and in view.
TEST(ReferencePoses, PaperLayoutsSeeTheOpenHand) {
  const HandModel model;
  for (const char* preset : {"paper-initial", "paper-optimized"}) {
    const Layout layout = load_layout_or_preset(test::asset_file(std::string("layouts/") + preset + ".json").string());
    for (int o = 0; o < kNumHandOrientations; ++o) {
      const PreparedFrame fr = prepare_frame(reference_pose(model, static_cast<HandOrientation>(o), HandMotion::kOpen));
      const Eigen::Vector3d a(fr.ax, fr.ay, fr.az);
      EXPECT_GT(a.dot(Eigen::Vector3d(0, 0, -1)), 0.0);
      const VisibilityTable t = compute_visibility(layout, std::span<const PreparedFrame>(&fr, 1));
      FingerBits any = 0;
      for (int d = 0; d < t.devices; ++d) any |= t.at(d, 0);
      std::string why;
      for (int d = 0; d < t.devices && std::string(preset) == "paper-initial"; ++d) {
        const auto ex = explain_visibility(fr, DeviceView::from_device(layout.devices[static_cast<size_t>(d)]),
                                           make_limits(VisibilityParams::from_sensor(common_sensor(layout))));
        for (int k = 0; k < kNumDigits; ++k)
          why += " | dev" + std::to_string(d) + " " + std::string(digit_name(k)) + ": " +
                 describe(ex.fingers[static_cast<size_t>(k)]);
      }
      const bool initial_vertical = std::string(preset) == "paper-initial" && o == 1;
      for (int d = 0; d < t.devices && std::string(preset) == "paper-initial"; ++d) {
        const auto ex = explain_visibility(fr, DeviceView::from_device(layout.devices[static_cast<size_t>(d)]),
                                           make_limits(VisibilityParams::from_sensor(common_sensor(layout))));
        for (const auto& v : ex.fingers) {
          EXPECT_TRUE(v.reason == HiddenReason::kVisible || v.reason == HiddenReason::kBehindFinger ||
                      v.reason == HiddenReason::kBehindPalm)
              << preset << " device " << d << ": " << describe(v);
        }
      }
      if (initial_vertical) {
        EXPECT_EQ(any & (1 << 2), 0) << "middle finger hidden from every device";
        continue;
      }
      EXPECT_EQ(any, kAllFingersVisible) << preset << " " << orientation_name(static_cast<HandOrientation>(o)) << why;
    }
  }
}

TEST(ReferencePoses, MotionPoseGoesFromTheOpenHandToTheEndOfRangeAtTheSimulatorsPlacement) {
  const HandModel model;
  const HandFrame open = motion_pose(model, HandOrientation::kHorizontal, HandMotion::kIndexFlexion, 0.0);
  const HandFrame flexed = motion_pose(model, HandOrientation::kHorizontal, HandMotion::kIndexFlexion, 1.0);
  const HandFrame half = motion_pose(model, HandOrientation::kHorizontal, HandMotion::kIndexFlexion, 0.5);
  EXPECT_TRUE(open.hand_present);
  // Placed like the simulated rig's trial hand: the open hand's placement throughout.
  const HandFrame sim_open =
      model.pose(motion_angles(HandMotion::kOpen, 0.0), reference_placement(model, HandOrientation::kHorizontal));
  for (int k = 0; k < kNumHandPoints; ++k) EXPECT_NEAR((open.point(k) - sim_open.point(k)).norm(), 0.0, 1e-9) << k;
  // The index tip curls towards the palm; the middle finger and the palm stay where they were.
  const int index_tip = digit_point(Digit::kIndex, Joint::kEnd);
  const int middle_tip = digit_point(Digit::kMiddle, Joint::kEnd);
  const double open_gap = (open.point(index_tip) - open.point(kPalm)).norm();
  const double flexed_gap = (flexed.point(index_tip) - flexed.point(kPalm)).norm();
  EXPECT_LT(flexed_gap, open_gap - 40.0);
  const double half_gap = (half.point(index_tip) - half.point(kPalm)).norm();
  EXPECT_LT(half_gap, open_gap);
  EXPECT_GT(half_gap, flexed_gap);
  EXPECT_NEAR((flexed.point(middle_tip) - open.point(middle_tip)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((flexed.point(kPalm) - open.point(kPalm)).norm(), 0.0, 1e-9);
  // Progress outside [0, 1] is held at the ends.
  const HandFrame beyond = motion_pose(model, HandOrientation::kHorizontal, HandMotion::kIndexFlexion, 1.7);
  EXPECT_NEAR((beyond.point(index_tip) - flexed.point(index_tip)).norm(), 0.0, 1e-9);
}

}  // namespace
}  // namespace lmc
