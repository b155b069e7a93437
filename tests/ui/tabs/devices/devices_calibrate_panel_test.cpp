// The Devices tab's Calibrate section drawn headless in every stage (idle, calibrating, result,
// applied) without an ImGui assertion, and its Ctrl+Z path: undo an applied calibration through
// the layout document's registered editor, and leave another last change alone.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>

#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "devices/sim/sim_rig.h"
#include "tests/support/reference_data.h"
#include "tests/ui/headless_imgui.h"
#include "tests/ui/last_status.h"
#include "ui/model/devices/devices_state.h"
#include "ui/model/layout/layout_actions.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/devices/devices_calibrate_panel.h"
#include "ui/tabs/tab.h"

namespace devices_calibrate_panel_test {

using lmc::ui::testing::LastStatus;

}  // namespace devices_calibrate_panel_test

TEST(DevicesCalibratePanel, DrawsEveryStageAndCtrlZUndoesTheAppliedCalibration) {
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");
  lmc::devices::SimConfig config;
  config.calibration_rotations_deg["LMC4"] = Eigen::Vector3d(0, 0, 5);
  const lmc::devices::SimTrial trial = lmc::devices::generate_sim_trial(layout, config, 3.0);
  lmc::LmcRecording rec;
  for (const auto& e : trial.events)
    if (e.is_frame) rec.rows.push_back(e.frame.frame);
  const auto file = lmc::test::scratch_dir("devices_calibrate_panel") / "LMC_Calibration.raw.txt";
  lmc::save_lmc_recording(file, rec);

  lmc::ui::WorkbenchContext context;
  context.layout().publish(layout);
  auto doc = lmc::ui::UndoableLayoutDocument(lmc::ui::make_document(layout));
  lmc::ui::DocumentLayoutEditor editor(doc);
  context.layout().set_editor(&editor);
  devices_calibrate_panel_test::LastStatus status;
  auto state = std::make_shared<lmc::ui::DevicesState>(
      context.rig(), context.layout(),
      [&status](const std::string& text, bool is_error) { status.set_status(text, is_error); });
  lmc::ui::DevicesCalibratePanel panel(state);
  lmc::ui::testing::HeadlessImGui ui;
  const auto body = [&] {
    state->update();
    panel.draw();
  };
  ui.frames(2, body);
  EXPECT_EQ(state->calibration().stage(), lmc::ui::CalibrationStage::kIdle);

  ASSERT_EQ(state->calibration().calibrate_file(file, layout, {}), "");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);
  while (state->calibration().busy() && std::chrono::steady_clock::now() < deadline) {
    ui.frame(body);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(state->calibration().stage(), lmc::ui::CalibrationStage::kResult) << state->calibration().message();
  ui.frames(2, body);
  EXPECT_NE(status.last.find("calibrated from Calibration"), std::string::npos) << status.last;
  EXPECT_FALSE(state->ghosts().empty()) << "the 3D view gets the comparison while the result waits";

  ASSERT_TRUE(state->calibration().apply(context.layout().editor()));
  ui.frames(2, body);
  EXPECT_TRUE(state->ghosts().empty());
  EXPECT_EQ(doc.head().layout.name, "paper-initial (calibrated)");
  state->undo_calibration();
  ui.frames(2, body);
  EXPECT_EQ(doc.head().layout, layout);
  EXPECT_EQ(state->calibration().stage(), lmc::ui::CalibrationStage::kResult);

  // Applied, then another edit: Ctrl+Z in the Devices tab says where to undo it instead.
  ASSERT_TRUE(state->calibration().apply(context.layout().editor()));
  ASSERT_TRUE(lmc::ui::rename_slot(doc, 1, "LMC2b"));
  state->undo_calibration();
  EXPECT_TRUE(status.error);
  EXPECT_NE(status.last.find("Layout tab"), std::string::npos) << status.last;
  EXPECT_EQ(doc.head().layout.devices[1].slot, "LMC2b");
  context.layout().set_editor(nullptr);
}
