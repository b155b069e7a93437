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

#include "core/common/paths.h"

namespace lmc::ui {

std::unique_ptr<Tab> make_devices_tab(StatusSink& status, WorkbenchContext& context) {
  return std::make_unique<DevicesTab>(status, context);
}

DevicesTab::DevicesTab(StatusSink& status, WorkbenchContext& context)
    : state_(std::make_shared<DevicesState>(
          context.rig(), context.layout(),
          [&status](const std::string& text, bool is_error) { status.set_status(text, is_error); })),
      toolbar_(state_),
      table_(state_),
      recording_(state_, sessions_dir() / "test-recordings"),
      live_hands_(state_),
      calibrate_(state_),
      log_(state_) {}

void DevicesTab::update(bool /*shown*/) {
  state_->update();
}

void DevicesTab::draw() {
  state_->auto_start();
  toolbar_.draw();
  ImGui::Separator();
  table_.draw();
  ImGui::Separator();
  recording_.draw();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float side_width = std::max(380.0F, avail.x * 0.36F);
  if (const auto window = live_hands_.window(ImVec2(avail.x - side_width - 8.0F, avail.y), true,
                                             ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse))
    live_hands_.draw();
  ImGui::SameLine();
  ImGui::BeginGroup();
  // The Calibrate step above the log: its result table needs most of the height while shown.
  const CalibrationStage stage = state_->calibration().stage();
  const bool result = stage == CalibrationStage::kResult || stage == CalibrationStage::kApplied;
  const float line = ImGui::GetFrameHeightWithSpacing();
  const float calibrate_height = result ? std::max(avail.y * 0.72F, avail.y - 6.0F * line) : 5.0F * line;
  if (const auto window = calibrate_.window(ImVec2(side_width, calibrate_height), true)) calibrate_.draw();
  if (const auto window = log_.window(ImVec2(side_width, 0), true)) log_.draw();
  ImGui::EndGroup();
  handle_shortcuts();
}

void DevicesTab::handle_shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
  if (io.KeyCtrl && !io.KeyShift && ImGui::IsKeyPressed('Z', false)) state_->undo_calibration();
}

}  // namespace lmc::ui
