#include "ui/model/layout/layout_actions.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/io/sensor_catalogue_json.h"

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

// ---- each controller's model and sensor -------------------------------------------------------

TEST(LayoutActions, SetDeviceModelChangesThatControllerOnlyAndNamesTheModel) {
  auto doc = paper_square();
  const LayoutDocument before = doc.head();
  ASSERT_TRUE(set_device_model(doc, 1, "lmc2"));
  const LayoutDevice& d = doc.head().layout.devices[1];
  EXPECT_EQ(d.model, "lmc2");
  EXPECT_DOUBLE_EQ(d.sensor.range_mm, 1100.0);
  EXPECT_DOUBLE_EQ(d.sensor.range_near_mm, 100.0);
  EXPECT_DOUBLE_EQ(d.sensor.fov_long_deg, 160.0);
  EXPECT_DOUBLE_EQ(d.sensor.fov_short_deg, 160.0);
  EXPECT_DOUBLE_EQ(d.sensor.axis_cut_mm, 666.0);
  EXPECT_DOUBLE_EQ(d.footprint_mm.x(), 84.0);
  EXPECT_DOUBLE_EQ(d.footprint_mm.y(), 20.0);
  for (int i : {0, 2, 3})
    EXPECT_EQ(doc.head().layout.devices[static_cast<size_t>(i)], before.layout.devices[static_cast<size_t>(i)]);
  EXPECT_EQ(doc.undo_message(), "Model of LMC2: Leap Motion Controller 2");
  EXPECT_EQ(doc.undo_size(), 1u);
  ASSERT_TRUE(set_device_model(doc, 1, "lmc2"));
  EXPECT_EQ(doc.undo_size(), 1u) << "the model it already is: no step";
  const ActionResult bad = set_device_model(doc, 1, "lmc9");
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.error.find("'lmc9'"), std::string::npos) << bad.error;
  EXPECT_NE(bad.error.find("lmc2"), std::string::npos) << "names the known models: " << bad.error;
}

TEST(LayoutActions, ASensorEditIsNamedForWhatChangedAndResetDropsTheOverride) {
  auto doc = paper_square();
  ASSERT_TRUE(set_device_model(doc, 2, "lmc"));
  SensorModel s = doc.head().layout.devices[2].sensor;
  s.range_mm = 450;
  for (double near : {105.0, 110.0, 120.0}) {
    SensorModel preview = s;
    preview.range_near_mm = near;
    ASSERT_TRUE(preview_device_sensor(doc, 2, preview));
  }
  EXPECT_DOUBLE_EQ(doc.head().layout.devices[2].sensor.range_near_mm, 100.0) << "previews leave the head alone";
  ASSERT_TRUE(set_device_sensor(doc, 2, s));
  EXPECT_EQ(doc.undo_message(), "Range of LMC3");
  EXPECT_DOUBLE_EQ(doc.head().layout.devices[2].sensor.range_mm, 450.0);
  EXPECT_DOUBLE_EQ(doc.head().layout.devices[2].sensor.range_near_mm, 100.0);
  EXPECT_EQ(doc.head().layout.devices[2].model, "lmc") << "an override keeps the model";
  s.fov_short_deg = 100;
  ASSERT_TRUE(set_device_sensor(doc, 2, s));
  EXPECT_EQ(doc.undo_message(), "Field of view of LMC3");
  s.range_near_mm = 50;
  s.axis_cut_mm = 300;
  ASSERT_TRUE(set_device_sensor(doc, 2, s));
  EXPECT_EQ(doc.undo_message(), "Sensor of LMC3");
  const size_t steps = doc.undo_size();
  ASSERT_TRUE(set_device_sensor(doc, 2, s));
  EXPECT_EQ(doc.undo_size(), steps) << "no change, no step";
  s.range_mm = -5;
  EXPECT_FALSE(set_device_sensor(doc, 2, s).ok) << "a negative range is refused";
  EXPECT_EQ(doc.undo_size(), steps);

  ASSERT_TRUE(reset_device_sensor(doc, 2));
  EXPECT_EQ(doc.undo_message(), "Reset LMC3 to its model");
  EXPECT_EQ(doc.head().layout.devices[2].sensor, sensor_catalogue().at("lmc", "test").sensor);
  doc.undo();
  EXPECT_DOUBLE_EQ(doc.head().layout.devices[2].sensor.axis_cut_mm, 300.0);
}

TEST(LayoutActions, EveryControllerTakesOneModelInOneStep) {
  auto doc = paper_square();
  ASSERT_TRUE(set_device_model(doc, 0, "lmc"));
  SensorModel s = doc.head().layout.devices[0].sensor;
  s.range_mm = 500;
  ASSERT_TRUE(set_device_sensor(doc, 0, s));
  const size_t steps = doc.undo_size();
  ASSERT_TRUE(set_every_device_model(doc, "lmc2"));
  EXPECT_EQ(doc.undo_size(), steps + 1);
  EXPECT_EQ(doc.undo_message(), "Model of every controller: Leap Motion Controller 2");
  for (const LayoutDevice& d : doc.head().layout.devices) {
    EXPECT_EQ(d.model, "lmc2");
    EXPECT_DOUBLE_EQ(d.sensor.range_mm, 1100.0) << d.slot << ": overrides dropped";
  }
  EXPECT_FALSE(set_every_device_model(doc, "nope").ok);
}

}  // namespace layout_actions_test
}  // namespace lmc::ui
