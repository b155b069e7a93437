// The Devices tab: every connected controller (or the simulated rig) with serial,
// slot (assign by dropdown), backend, model, tracking mode, status, rate, hand present and latest
// frame age; a live 3-D view of every device's hand realigned into the world frame, one colour per
// device, so a misplaced controller shows at a glance; start/stop of a test recording through the
// one trial engine; the Calibrate step above the device log. It drives the workbench's live rig
// (shared with the Record tab) with the layout open in the Layout tab. Its state is
// ui/model/devices/devices_state.h; the panels beside this file draw it (toolbar, device table, test
// recording, live hands, calibrate, device log) and this file lays them out.
#include "ui/tabs/devices/devices_tab.h"

#include <imgui.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "core/common/paths.h"
#include "ui/model/devices/devices_state.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/capture_scratch.h"
#include "ui/tabs/devices/device_log_panel.h"
#include "ui/tabs/devices/device_table_panel.h"
#include "ui/tabs/devices/devices_calibrate_panel.h"
#include "ui/tabs/devices/devices_toolbar_panel.h"
#include "ui/tabs/devices/live_hands_panel.h"
#include "ui/tabs/devices/test_recording_panel.h"

namespace lmc::ui {
namespace {

class DevicesTab final : public Tab {
 public:
  DevicesTab(StatusSink& status, WorkbenchContext& context)
      : state_(std::make_shared<DevicesState>(
            context.rig(), context.layout(),
            [&status](const std::string& text, bool is_error) { status.set_status(text, is_error); })),
        toolbar_(state_),
        table_(state_),
        recording_(state_, sessions_dir() / "test-recordings"),
        live_hands_(state_),
        calibrate_(state_),
        log_(state_) {}

  void update(bool /*shown*/) override { state_->update(); }

  void draw() override {
    state_->auto_start();
    toolbar_.draw();
    ImGui::Separator();
    table_.draw();
    ImGui::Separator();
    recording_.draw();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float side_width = std::max(380.0F, avail.x * 0.36F);
    ImGui::BeginChild("live_view", ImVec2(avail.x - side_width - 8.0F, avail.y), true,
                      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    live_hands_.draw();
    ImGui::EndChild();
    ImGui::SameLine();
    ImGui::BeginGroup();
    // The Calibrate step above the log: its result table needs most of the height while shown.
    const CalibrationStage stage = state_->calibration().stage();
    const bool result = stage == CalibrationStage::kResult || stage == CalibrationStage::kApplied;
    const float line = ImGui::GetFrameHeightWithSpacing();
    const float calibrate_height = result ? std::max(avail.y * 0.72F, avail.y - 6.0F * line) : 5.0F * line;
    ImGui::BeginChild("calibrate", ImVec2(side_width, calibrate_height), true);
    calibrate_.draw();
    ImGui::EndChild();
    ImGui::BeginChild("device_log", ImVec2(side_width, 0), true);
    log_.draw();
    ImGui::EndChild();
    ImGui::EndGroup();
    handle_shortcuts();
  }

  int prepare_for_capture() override {
    const DevicesViewModel& vm = state_->view();
    if (!vm.running() || vm.backend() != "sim") state_->start("sim");
    return 30;
  }

  bool busy_for_capture() const override {
    const DevicesViewModel& vm = state_->view();
    return (vm.running() && !vm.all_streaming()) || state_->calibration().busy();
  }

  // devices-calibrate: a finished calibration on the simulated rig with injected errors (three
  // controllers turned, every controller shifted up to 15 mm), so the corrections and the ghost
  // controllers show.
  std::vector<std::string> extra_captures() const override { return {"devices-calibrate"}; }

  void prepare_extra_capture(const std::string& name) override {
    if (name != "devices-calibrate") return;
    devices::SimConfig sim;
    sim.calibration_rotations_deg["LMC2"] = Eigen::Vector3d(0, 6, 0);
    sim.calibration_rotations_deg["LMC3"] = Eigen::Vector3d(4, 0, 0);
    sim.calibration_rotations_deg["LMC4"] = Eigen::Vector3d(0, 0, -3);
    sim.calibration_random_translation_mm = 15;
    if (!state_->start("sim", sim).empty()) return;
    const auto dir = capture_scratch_.fresh("calibration");
    if (const std::string err = state_->calibration().record(dir, {}); !err.empty()) state_->report(err, true);
  }

 private:
  void handle_shortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
    if (io.KeyCtrl && !io.KeyShift && ImGui::IsKeyPressed('Z', false)) state_->undo_calibration();
  }

  CaptureScratch capture_scratch_;       // before state_ and the panels: removed after they stop recording
  std::shared_ptr<DevicesState> state_;  // the panels share it
  DevicesToolbarPanel toolbar_;
  DeviceTablePanel table_;
  TestRecordingPanel recording_;
  LiveHandsPanel live_hands_;
  DevicesCalibratePanel calibrate_;
  DeviceLogPanel log_;
};

}  // namespace

std::unique_ptr<Tab> make_devices_tab(StatusSink& status, WorkbenchContext& context) {
  return std::make_unique<DevicesTab>(status, context);
}

}  // namespace lmc::ui
