// The Devices tab's Calibrate step, model side: the stages idle → recording →
// calibrating → result → applied / discarded, cancel at each running stage, the 3D view's ghost
// controllers built from a result, Apply as one undo step that Ctrl+Z takes back, and Save writing
// a layout that reads back to the corrected poses. Waits poll a condition with a generous
// deadline; no timed asserts.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <thread>

#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "devices/sim/sim_rig.h"
#include "tests/support/reference_data.h"
#include "ui/model/devices/calibration_step.h"
#include "ui/model/workbench_context.h"
#include "ui/scene/calibration_ghosts.h"

namespace calibration_step_test {

// Polls the rig and the step until `done` holds (the workers run under sanitizers in CI).
bool update_until(lmc::ui::LiveRig& rig, lmc::ui::CalibrationStep& step, const std::function<bool()>& done) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);
  for (;;) {
    rig.poll();
    step.update();
    if (done()) return true;
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

// A simulated still-hand trial of `seconds` on `layout` with LMC2 turned 6° about y, as a file.
std::filesystem::path simulated_trial_file(const lmc::Layout& layout, const std::string& folder, double seconds = 5.0) {
  lmc::devices::SimConfig config;
  config.calibration_rotations_deg["LMC2"] = Eigen::Vector3d(0, 6, 0);
  const lmc::devices::SimTrial trial = lmc::devices::generate_sim_trial(layout, config, seconds);
  lmc::LmcRecording rec;
  for (const auto& e : trial.events)
    if (e.is_frame) rec.rows.push_back(e.frame.frame);
  const auto file = lmc::test::scratch_dir(folder) / "LMC_Calibration.raw.txt";
  lmc::save_lmc_recording(file, rec);
  return file;
}

// A workbench context (one layout, one rig) showing `layout`, as the Layout tab would publish it.
struct Bench {
  lmc::ui::WorkbenchContext context;
  lmc::ui::CalibrationStep step{context.rig()};
  explicit Bench(const lmc::Layout& layout) { context.layout().publish(layout); }
};

size_t count_items(const std::vector<lmc::ui::SceneItem>& items, lmc::ui::ItemRole role, lmc::ui::ItemKind kind) {
  size_t n = 0;
  for (const auto& it : items) n += it.role == role && it.kind == kind ? 1 : 0;
  return n;
}

}  // namespace calibration_step_test

TEST(CalibrationGhosts, CurrentControllersAreGhostsAndCalibratedOnesSolidWithALineWhereOneMoved) {
  const lmc::Layout current = lmc::load_layout_or_preset("paper-initial");
  lmc::Layout calibrated = current;
  calibrated.devices[1].offset_mm = Eigen::Vector3d(12, 0, -5);
  const auto items = lmc::ui::calibration_ghost_items(current, calibrated);
  using lmc::ui::ItemKind;
  using lmc::ui::ItemRole;
  EXPECT_EQ(calibration_step_test::count_items(items, ItemRole::kGhost, ItemKind::kBox), 4u);
  EXPECT_EQ(calibration_step_test::count_items(items, ItemRole::kDevice, ItemKind::kBox), 4u);
  ASSERT_EQ(calibration_step_test::count_items(items, ItemRole::kGhost, ItemKind::kSegment), 1u) << "only LMC2 moved";
  for (const auto& it : items) {
    const bool ghost = (it.flags & lmc::ui::kFlagGhost) != 0;
    EXPECT_EQ(ghost, it.role == ItemRole::kGhost);
    if (it.kind == ItemKind::kSegment) {
      EXPECT_EQ(it.id, 1);
      EXPECT_NEAR((it.b - it.a).norm(), (calibrated.devices[1].offset_mm - current.devices[1].offset_mm).norm(), 1e-9);
    }
    if (it.kind != ItemKind::kBox) continue;
    const lmc::Layout& l = ghost ? current : calibrated;
    const auto origin = it.transform.translation();
    EXPECT_NEAR((origin - l.devices[static_cast<size_t>(it.id)].to_world(Eigen::Vector3d::Zero())).norm(), 0.0, 1e-9);
    // The top face is the controller's glass: y = 0 in its own frame, 80 × 30 mm around its origin.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& c : lmc::ui::box_top_face(it)) centre += c / 4.0;
    EXPECT_NEAR((centre - origin).norm(), 0.0, 1e-9);
    const auto face = lmc::ui::box_top_face(it);
    EXPECT_NEAR((face[1] - face[0]).norm(), 80.0, 1e-9);
    EXPECT_NEAR((face[2] - face[1]).norm(), 30.0, 1e-9);
    // Every box edge is one of the case's three dimensions (the study's model: 80 × 11.3 × 30 mm).
    for (const auto& e : lmc::ui::box_edges(it)) {
      const double len = (e[1] - e[0]).norm();
      EXPECT_TRUE(std::abs(len - 80) < 1e-9 || std::abs(len - 11.3) < 1e-9 || std::abs(len - 30) < 1e-9) << len;
    }
  }
  // A slot the calibrated layout lacks keeps only its ghost.
  calibrated.devices.pop_back();
  const auto fewer = lmc::ui::calibration_ghost_items(current, calibrated);
  EXPECT_EQ(calibration_step_test::count_items(fewer, ItemRole::kDevice, ItemKind::kBox), 3u);
  EXPECT_EQ(calibration_step_test::count_items(fewer, ItemRole::kGhost, ItemKind::kBox), 4u);
}

TEST(CalibrationStep, RecordedTrialGoesThroughResultApplyUndoAndDiscard) {
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");
  calibration_step_test::Bench b(layout);
  const auto file = calibration_step_test::simulated_trial_file(layout, "calibration_step_apply");
  auto& step = b.step;
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kIdle);
  EXPECT_TRUE(step.ghosts().empty());
  ASSERT_EQ(step.calibrate_file(file, layout, {}), "");
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kCalibrating);
  EXPECT_NE(step.calibrate_file(file, layout, {}), "") << "one calibration at a time";
  ASSERT_TRUE(calibration_step_test::update_until(b.context.rig(), step, [&] { return !step.busy(); }));
  ASSERT_EQ(step.stage(), lmc::ui::CalibrationStage::kResult) << step.message();
  ASSERT_NE(step.outcome(), nullptr);
  EXPECT_EQ(step.outcome()->trial, "Calibration");

  // One row per controller; LMC2 was turned 6°, so relative to the others it turns back the most.
  const auto rows = step.rows();
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[1].slot, "LMC2");
  for (const auto& r : rows) {
    EXPECT_TRUE(r.fitted) << r.slot;
    EXPECT_GT(r.samples, 100) << r.slot;
    EXPECT_LT(r.after_mm, r.before_mm) << r.slot;
    if (r.slot != "LMC2") {
      EXPECT_LT(r.turned_deg, rows[1].turned_deg) << r.slot;
    }
  }
  EXPECT_GT(rows[1].turned_deg, 3.0);
  EXPECT_LT(step.outcome()->result.disagreement_after_mm, 0.5 * step.outcome()->result.disagreement_before_mm);

  // The 3D view: four ghosts where the controllers stand now, four solid where they belong.
  const auto ghosts = step.ghosts();
  EXPECT_EQ(calibration_step_test::count_items(ghosts, lmc::ui::ItemRole::kGhost, lmc::ui::ItemKind::kBox), 4u);
  EXPECT_EQ(calibration_step_test::count_items(ghosts, lmc::ui::ItemRole::kDevice, lmc::ui::ItemKind::kBox), 4u);

  // Apply: one undo step in the document; no editor: refused with a reason.
  EXPECT_FALSE(step.apply(nullptr));
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kResult);
  auto doc = lmc::ui::UndoableLayoutDocument(lmc::ui::make_document(layout));
  lmc::ui::DocumentLayoutEditor editor(doc);
  const auto before = doc.head();
  ASSERT_TRUE(step.apply(&editor));
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kApplied);
  EXPECT_TRUE(step.ghosts().empty()) << "applied: the view shows the layout itself again";
  EXPECT_EQ(doc.undo_size(), 1u);
  EXPECT_EQ(doc.head().layout.name, "paper-initial (calibrated)");
  for (size_t d = 0; d < layout.devices.size(); ++d) {
    EXPECT_EQ(doc.head().layout.devices[d].pose, step.outcome()->calibrated.devices[d].pose);
    EXPECT_EQ(doc.head().layout.devices[d].offset_mm, step.outcome()->calibrated.devices[d].offset_mm);
  }

  // Ctrl+Z: the document is back where it was and the result waits again.
  ASSERT_TRUE(step.undo_apply(&editor));
  EXPECT_EQ(doc.head(), before);
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kResult);
  EXPECT_FALSE(step.undo_apply(&editor)) << "nothing applied to undo";

  // Applied, then undone in the Layout tab: the step notices and the result waits again.
  ASSERT_TRUE(step.apply(&editor));
  step.notice_layout(doc.head().layout);
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kApplied) << "the layout holds the calibration";
  doc.undo();
  step.notice_layout(doc.head().layout);
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kResult);
  EXPECT_NE(step.message().find("no longer holds"), std::string::npos) << step.message();

  // Another change after Apply: Ctrl+Z here leaves it alone.
  ASSERT_TRUE(step.apply(&editor));
  ASSERT_TRUE(lmc::ui::rename_slot(doc, 0, "LMC1b"));
  EXPECT_FALSE(step.undo_apply(&editor));
  EXPECT_EQ(doc.head().layout.devices[0].slot, "LMC1b");

  step.discard();
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kIdle);
  EXPECT_EQ(step.outcome(), nullptr);
  EXPECT_TRUE(step.ghosts().empty());
}

TEST(CalibrationStep, SaveWritesALayoutThatReadsBackToTheCorrectedPoses) {
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");
  calibration_step_test::Bench b(layout);
  const auto file = calibration_step_test::simulated_trial_file(layout, "calibration_step_save");
  auto& step = b.step;
  EXPECT_NE(step.save(file.parent_path() / "nothing.json"), "") << "no result yet";
  ASSERT_EQ(step.calibrate_file(file, layout, {}), "");
  ASSERT_TRUE(calibration_step_test::update_until(b.context.rig(), step, [&] { return !step.busy(); }));
  ASSERT_EQ(step.stage(), lmc::ui::CalibrationStage::kResult) << step.message();
  EXPECT_EQ(step.suggested_file_name(), "paper-initial-calibrated.json");
  const auto out = file.parent_path() / step.suggested_file_name();
  ASSERT_EQ(step.save(out), "");
  const lmc::Layout back = lmc::load_layout(out);
  EXPECT_EQ(back.name, "paper-initial (calibrated)");
  EXPECT_NE(back.description.find("from trial Calibration"), std::string::npos) << back.description;
  EXPECT_NE(back.description.find("without Vicon"), std::string::npos) << back.description;
  EXPECT_NE(back.description.find(" on 20"), std::string::npos) << "the date: " << back.description;
  const lmc::Layout& want = step.outcome()->calibrated;
  ASSERT_EQ(back.devices.size(), want.devices.size());
  for (size_t d = 0; d < want.devices.size(); ++d) {
    const Eigen::Vector3d p(10, 20, 30);
    EXPECT_NEAR((back.devices[d].to_world(p) - want.devices[d].to_world(p)).norm(), 0.0, 1e-6) << want.devices[d].slot;
  }
  // LMC2's saved pose differs from the nominal one: the correction was written, not the input
  // (LMC2 was turned about its y axis, so a point off that axis shows it).
  const Eigen::Vector3d p(100, 200, 50);
  EXPECT_GT((back.devices[1].to_world(p) - layout.devices[1].to_world(p)).norm(), 5.0);
}

TEST(CalibrationStep, CancelWhileCalibratingDropsTheResultAndAMissingFileSaysWhich) {
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");
  calibration_step_test::Bench b(layout);
  const auto file = calibration_step_test::simulated_trial_file(layout, "calibration_step_cancel");
  auto& step = b.step;
  ASSERT_EQ(step.calibrate_file(file, layout, {}), "");
  step.cancel();
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kIdle);
  EXPECT_EQ(step.message(), "calibration cancelled");
  // However long the worker takes to return, its result never counts.
  for (int i = 0; i < 50; ++i) {
    step.update();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kIdle);
  EXPECT_EQ(step.outcome(), nullptr);

  const auto missing = file.parent_path() / "LMC_Nothing.raw.txt";
  ASSERT_EQ(step.calibrate_file(missing, layout, {}), "");
  ASSERT_TRUE(calibration_step_test::update_until(b.context.rig(), step, [&] { return !step.busy(); }));
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kIdle);
  EXPECT_TRUE(step.message_is_error());
  EXPECT_NE(step.message().find("LMC_Nothing.raw.txt"), std::string::npos) << step.message();

  // With a Vicon file that does not exist the error names it too.
  lmc::ui::CalibrationSettings vicon;
  vicon.vicon = file.parent_path() / "none.trc";
  ASSERT_EQ(step.calibrate_file(file, layout, vicon), "");
  ASSERT_TRUE(calibration_step_test::update_until(b.context.rig(), step, [&] { return !step.busy(); }));
  EXPECT_NE(step.message().find("none.trc: no such Vicon file"), std::string::npos) << step.message();
}

TEST(CalibrationStep, RecordsAStillHandOnTheSimulatedRigThenCalibratesIt) {
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");
  calibration_step_test::Bench b(layout);
  auto& rig = b.context.rig();
  auto& step = b.step;
  const auto dir = lmc::test::scratch_dir("calibration_step_record");
  EXPECT_NE(step.record(dir, {}), "") << "no rig running";
  lmc::devices::SimConfig sim;
  sim.calibration_rotations_deg["LMC3"] = Eigen::Vector3d(5, 0, 0);
  ASSERT_EQ(rig.start("sim", sim), "");
  // 2 s keep the test short; the tab records 5 s.
  ASSERT_EQ(step.record(dir, {}, 2.0), "");
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kRecording);
  EXPECT_FALSE(step.activity().empty());
  ASSERT_TRUE(calibration_step_test::update_until(
      rig, step, [&] { return step.stage() != lmc::ui::CalibrationStage::kRecording; }));
  ASSERT_TRUE(calibration_step_test::update_until(rig, step, [&] { return !step.busy(); }));
  ASSERT_EQ(step.stage(), lmc::ui::CalibrationStage::kResult) << step.message();
  EXPECT_TRUE(std::filesystem::exists(dir / "LMC_Calibration.raw.txt"));
  const auto rows = step.rows();
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& r : rows) {
    if (r.slot != "LMC3") {
      EXPECT_LT(r.turned_deg, rows[2].turned_deg) << r.slot;
    }
  }
  // Serials bound on the rig are part of the layout the trial was recorded with.
  EXPECT_EQ(step.nominal().devices.size(), 4u);
}

TEST(CalibrationStep, CancelWhileRecordingEndsTheTrialAndReturnsToIdle) {
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");
  calibration_step_test::Bench b(layout);
  auto& rig = b.context.rig();
  auto& step = b.step;
  ASSERT_EQ(rig.start("sim"), "");
  const auto dir = lmc::test::scratch_dir("calibration_step_record_cancel");
  ASSERT_EQ(step.record(dir, {}, 60.0), "");
  step.cancel();
  ASSERT_TRUE(calibration_step_test::update_until(rig, step, [&] { return !step.busy(); }));
  EXPECT_EQ(step.stage(), lmc::ui::CalibrationStage::kIdle);
  EXPECT_FALSE(step.message_is_error());
  EXPECT_NE(step.message().find("cancelled"), std::string::npos) << step.message();
  EXPECT_EQ(step.outcome(), nullptr);
  EXPECT_FALSE(rig.recording());
}

TEST(CalibrationStep, TheSharedRealTrialCalibratesAndTheControllersAgreeBetter) {
  const auto file = lmc::test::reference_file("validation/Interp_LMC_Naiv_Static101.txt");
  LMC_REQUIRE_REFERENCE_FILE(file);
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");
  calibration_step_test::Bench b(layout);
  auto& step = b.step;
  ASSERT_EQ(step.calibrate_file(file, layout, {}), "");
  ASSERT_TRUE(calibration_step_test::update_until(b.context.rig(), step, [&] { return !step.busy(); }));
  ASSERT_EQ(step.stage(), lmc::ui::CalibrationStage::kResult) << step.message();
  const auto& r = step.outcome()->result;
  // The figures of docs/guide/calibrate.md (paper-initial with the authors'
  // offsets 5.2 mm, calibrated without Vicon 2.0 mm).
  EXPECT_NEAR(r.disagreement_before_mm, 5.2, 0.1);
  EXPECT_NEAR(r.disagreement_after_mm, 2.0, 0.1);
  EXPECT_EQ(step.rows().size(), 4u);
}
