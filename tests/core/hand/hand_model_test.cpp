#include "core/hand/hand_model.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

#include "core/hand/reference_poses.h"
#include "core/io/lmc_recording.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace {

double dist(const HandFrame& f, int a, int b) {
  return (f.point(a) - f.point(b)).norm();
}

TEST(HandModel, DefaultSegmentLengthsFollowBuchholz) {
  const HandModel model;  // HL 190 mm
  const HandFrame f = model.pose({});
  // Index proximal phalanx 0.265·HL, middle distal 0.108·HL, thumb distal 0.158·HL.
  EXPECT_NEAR(dist(f, digit_point(1, 1), digit_point(1, 2)), 0.265 * 190, 1e-9);
  EXPECT_NEAR(dist(f, digit_point(2, 3), digit_point(2, 4)), 0.108 * 190, 1e-9);
  EXPECT_NEAR(dist(f, digit_point(0, 3), digit_point(0, 4)), 0.158 * 190, 1e-9);
  // Thumb metacarpal 0.251·HL between CMC (Proxi) and MCP (Inter); Meta == Proxi.
  EXPECT_NEAR(dist(f, digit_point(0, 1), digit_point(0, 2)), 0.251 * 190, 1e-9);
  EXPECT_EQ(f.point(digit_point(0, 0)), f.point(digit_point(0, 1)));
  // Index metacarpal 0.374·HL.
  EXPECT_NEAR(dist(f, digit_point(1, 0), digit_point(1, 1)), 0.374 * 190, 1e-9);
}

TEST(HandModel, CanonicalFrameFingersForwardPalmDownThumbLeft) {
  const HandModel model;
  const HandFrame f = model.pose({});
  EXPECT_LT(f.point(digit_point(2, 4)).z(), -150.0);  // middle tip far along −z
  EXPECT_GT(f.point(kElbow).z(), 200.0);              // elbow towards the subject
  EXPECT_NEAR(f.point(kPalmNormal).y(), -1.0, 1e-12);
  EXPECT_NEAR(f.point(kPalmDirection).z(), -1.0, 1e-12);
  EXPECT_LT(f.point(digit_point(0, 4)).x(), f.point(digit_point(1, 4)).x());  // thumb on −x
  EXPECT_LT(f.point(digit_point(1, 1)).x(), f.point(digit_point(4, 1)).x());  // index MCP left of pinky MCP
}

TEST(HandModel, FlexionBendsTowardsThePalm) {
  const HandModel model;
  HandJointAngles a;
  a.finger(Digit::kIndex) = {90, 0, 90, 0};
  const HandFrame f = model.pose(a);
  const Eigen::Vector3d mcp = f.point(digit_point(1, 1)), pip = f.point(digit_point(1, 2));
  EXPECT_NEAR(pip.y() - mcp.y(), -0.265 * 190, 1e-9);  // proximal phalanx straight down
  const Eigen::Vector3d dip = f.point(digit_point(1, 3));
  EXPECT_GT(dip.z(), pip.z() + 20);  // middle phalanx points back towards the wrist
  HandJointAngles w;
  w.wrist_flexion_deg = 60;
  EXPECT_LT(model.pose(w).point(kPalmDirection).y(), -0.8);
  EXPECT_NEAR(model.pose(w).point(kElbow).z(), model.pose({}).point(kElbow).z(), 1e-9);  // forearm stays
}

TEST(HandModel, JointParamAccessRoundTrips) {
  HandJointAngles a;
  for (int k = 0; k < kNumHandJointParams; ++k) set_joint_param(a, k, 1.0 + k);
  for (int k = 0; k < kNumHandJointParams; ++k) EXPECT_EQ(joint_param(a, k), 1.0 + k) << joint_param_name(k);
  EXPECT_EQ(a.finger(Digit::kRing).pip_flexion_deg, 1.0 + 6 + 2 * 4 + 2);
}

TEST(HandModel, FromRecordedFrameKeepsItsLengths) {
  const auto path = test::reference_file("optimization/Static.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const LmcRecording rec = read_lmc_recording(path);
  ASSERT_FALSE(rec.rows.empty());
  const HandFrame& row = rec.rows.front();
  ASSERT_TRUE(row.hand_present);
  const HandModel model(row);
  const HandFrame f = model.pose({});
  for (int d = 1; d < kNumDigits; ++d) {
    for (int j = 1; j < 4; ++j) {
      EXPECT_NEAR(dist(f, digit_point(d, j), digit_point(d, j + 1)),
                  dist(row, digit_point(d, j), digit_point(d, j + 1)), 1e-9)
          << d << "/" << j;
    }
    EXPECT_NEAR(dist(f, digit_point(d, 0), digit_point(d, 1)), dist(row, digit_point(d, 0), digit_point(d, 1)), 1e-9);
  }
  EXPECT_NEAR(dist(f, kElbow, kWrist), dist(row, kElbow, kWrist), 1e-9);
  EXPECT_NEAR(dist(f, digit_point(0, 1), digit_point(0, 2)), dist(row, digit_point(0, 1), digit_point(0, 2)), 1e-9);
  // The recorded metacarpal bases sit where they were relative to the wrist.
  EXPECT_NEAR(dist(f, kWrist, digit_point(2, 0)), dist(row, kWrist, digit_point(2, 0)), 1e-9);
}

TEST(HandModel, RejectsAFrameWithoutHand) {
  HandFrame empty;
  EXPECT_THROW(HandModel{empty}, lmc::Error);
}

}  // namespace
}  // namespace lmc
