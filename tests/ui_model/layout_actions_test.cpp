#include "ui/model/layout_actions.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lmc::ui {
namespace layout_actions_test {

UndoableLayoutDocument paper_square() {
  return UndoableLayoutDocument(make_document(default_new_layout()));
}

TEST(LayoutActions, SetPoseParamCommitsOneStepThatUndoRestoresExactly) {
  auto doc = paper_square();
  const LayoutDocument before = doc.head();
  ASSERT_TRUE(set_pose_param(doc, 1, 3, 12.5));
  EXPECT_DOUBLE_EQ(doc.head().layout.devices[1].pose.rx_deg, 12.5);
  EXPECT_EQ(doc.undo_size(), 1u);
  EXPECT_EQ(doc.undo_message(), "Set LMC2 rx");
  doc.undo();
  EXPECT_EQ(doc.head(), before);
  doc.redo();
  EXPECT_DOUBLE_EQ(doc.head().layout.devices[1].pose.rx_deg, 12.5);
}

TEST(LayoutActions, PreviewThenCommitIsOneUndoStep) {
  auto doc = paper_square();
  const LayoutDocument before = doc.head();
  DevicePose p = before.layout.devices[0].pose;
  for (int i = 1; i <= 10; ++i) {
    p.x_mm = -60.0 + i * 3.0;
    ASSERT_TRUE(preview_device_pose(doc, 0, p));
  }
  EXPECT_EQ(doc.head(), before) << "previews must not touch the head";
  EXPECT_TRUE(commit_device_pose(doc, 0, "Move"));
  EXPECT_EQ(doc.undo_size(), 1u);
  EXPECT_EQ(doc.undo_message(), "Move LMC1");
  EXPECT_DOUBLE_EQ(doc.head().layout.devices[0].pose.x_mm, -30.0);
  doc.undo();
  EXPECT_EQ(doc.head(), before);
}

TEST(LayoutActions, CancelledPreviewLeavesNoTrace) {
  auto doc = paper_square();
  DevicePose p;
  p.x_mm = 500;
  ASSERT_TRUE(preview_device_pose(doc, 2, p));
  cancel_preview(doc);
  EXPECT_EQ(doc.scratch(), doc.head());
  EXPECT_FALSE(doc.can_undo());
}

TEST(LayoutActions, AddAndRemoveDevicesKeepLocksParallelAndRespectLimits) {
  auto doc = paper_square();
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(add_device(doc));
  EXPECT_EQ(doc.head().device_count(), 8);
  EXPECT_EQ(doc.head().locks.size(), 8u);
  EXPECT_EQ(doc.head().layout.devices[4].slot, "LMC5");
  const auto commits = doc.undo_size();
  const ActionResult too_many = add_device(doc);
  EXPECT_FALSE(too_many);
  EXPECT_NE(too_many.error.find("at most 8"), std::string::npos);
  EXPECT_EQ(doc.undo_size(), commits) << "a rejected action leaves no commit";
  while (doc.head().device_count() > 1) ASSERT_TRUE(remove_device(doc, 0));
  EXPECT_FALSE(remove_device(doc, 0));
  EXPECT_EQ(doc.head().locks.size(), 1u);
  EXPECT_EQ(doc.undo_message(), "Remove LMC7");
}

TEST(LayoutActions, RenameRejectsDuplicatesAndEmptyNames) {
  auto doc = paper_square();
  EXPECT_FALSE(rename_slot(doc, 0, "LMC2"));
  EXPECT_FALSE(rename_slot(doc, 0, ""));
  EXPECT_FALSE(doc.can_undo());
  ASSERT_TRUE(rename_slot(doc, 0, "left-front"));
  EXPECT_EQ(doc.head().layout.devices[0].slot, "left-front");
  EXPECT_EQ(doc.undo_message(), "Rename LMC1 to left-front");
}

TEST(LayoutActions, SerialsAreUniqueAndCanBeCleared) {
  auto doc = paper_square();
  ASSERT_TRUE(assign_serial(doc, 0, "LP111"));
  const ActionResult clash = assign_serial(doc, 1, "LP111");
  EXPECT_FALSE(clash);
  EXPECT_NE(clash.error.find("LMC1"), std::string::npos);
  EXPECT_EQ(doc.scratch(), doc.head());
  ASSERT_TRUE(assign_serial(doc, 0, ""));
  EXPECT_FALSE(doc.head().layout.devices[0].serial.has_value());
}

TEST(LayoutActions, LocksAreDocumentStateAndUndoable) {
  auto doc = paper_square();
  EXPECT_TRUE(doc.head().locks[0].locked[1]) << "y is locked by default (the paper searched x, z, rx, ry)";
  ASSERT_TRUE(set_device_lock(doc, 0, 0, true));
  EXPECT_TRUE(doc.head().locks[0].locked[0]);
  doc.undo();
  EXPECT_FALSE(doc.head().locks[0].locked[0]);
}

TEST(LayoutActions, MakingADeviceStayPutIsOneStep) {
  auto doc = paper_square();
  ASSERT_TRUE(set_device_movable(doc, 1, false));
  EXPECT_EQ(doc.undo_size(), 1u);
  EXPECT_EQ(doc.undo_message(), "LMC2 stays put");
  for (bool l : doc.head().locks[1].locked) EXPECT_TRUE(l);
  ASSERT_TRUE(set_device_movable(doc, 1, true));
  EXPECT_EQ(doc.head().locks[1], DeviceLocks{});
}

TEST(LayoutActions, ApplyLayoutMatchesBySlotAndIsOneUndoStep) {
  auto doc = paper_square();
  const LayoutDocument before = doc.head();
  Layout optimised = before.layout;
  optimised.devices[3].pose.x_mm = 178.88;
  optimised.devices[3].pose.ry_deg = 12.38;
  std::swap(optimised.devices[0], optimised.devices[3]);  // order must not matter
  optimised.name = "optimized-robust";
  optimised.description = "Optimiser panel, robust metric: 30 particles x 100 iterations";
  ASSERT_TRUE(apply_layout(doc, optimised));
  EXPECT_DOUBLE_EQ(doc.head().layout.devices[3].pose.x_mm, 178.88);
  // The applied layout says what made it, not the start's name.
  EXPECT_EQ(doc.head().layout.name, "optimized-robust");
  EXPECT_EQ(doc.head().layout.description, optimised.description);
  EXPECT_EQ(doc.head().layout.devices[3].slot, "LMC4");
  EXPECT_EQ(doc.undo_size(), 1u);
  EXPECT_EQ(doc.undo_message(), "Apply optimised layout");
  doc.undo();
  EXPECT_EQ(doc.head(), before);
}

TEST(LayoutActions, ApplyCalibrationSetsPosesOffsetsAndNameInOneUndoStep) {
  auto doc = paper_square();
  const LayoutDocument before = doc.head();
  Layout calibrated = before.layout;
  calibrated.name = "untitled (calibrated)";
  calibrated.description = "Calibrated 4 of 4 controllers from trial T";
  calibrated.devices[2].pose.ry_deg = 3.5;
  calibrated.devices[2].offset_mm = Eigen::Vector3d(4, -2, 11);
  ASSERT_TRUE(apply_calibration(doc, calibrated));
  EXPECT_EQ(doc.head().layout, calibrated);
  EXPECT_EQ(doc.undo_size(), 1u);
  EXPECT_EQ(doc.undo_message(), "Apply calibration");
  doc.undo();
  EXPECT_EQ(doc.head(), before);
  calibrated.devices[1].offset_mm.x() = std::nan("");
  const ActionResult bad = apply_calibration(doc, calibrated);
  EXPECT_FALSE(bad);
  EXPECT_EQ(bad.error, "the calibrated pose of LMC2 is not finite");
  EXPECT_EQ(doc.head(), before);
}

TEST(LayoutActions, ReplaceLayoutKeepsLocksOfSurvivingSlots) {
  auto doc = paper_square();
  ASSERT_TRUE(set_device_lock(doc, 1, 2, true));
  Layout other = default_new_layout();
  other.devices.erase(other.devices.begin());  // LMC2 is now index 0
  ASSERT_TRUE(replace_layout(doc, other, "Open other.json"));
  ASSERT_EQ(doc.head().locks.size(), 3u);
  EXPECT_TRUE(doc.head().locks[0].locked[2]);
  EXPECT_EQ(doc.undo_message(), "Open other.json");
}

TEST(UndoRedo, HeadIdReturnsAfterUndoRedoAndCommitClearsRedo) {
  UndoRedo<int> u(0);
  const auto id0 = u.head_id();
  u.upd_scratch() = 1;
  ASSERT_TRUE(u.commit("one"));
  const auto id1 = u.head_id();
  EXPECT_NE(id0, id1);
  u.undo();
  EXPECT_EQ(u.head_id(), id0);
  u.redo();
  EXPECT_EQ(u.head_id(), id1);
  u.undo();
  u.upd_scratch() = 2;
  u.commit("two");
  EXPECT_FALSE(u.can_redo());
  EXPECT_EQ(u.head(), 2);
  EXPECT_FALSE(u.commit("nothing changed"));
}

}  // namespace layout_actions_test
}  // namespace lmc::ui
