#include "ui/tabs/devices/devices_calibrate_panel.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/common/paths.h"
#include "ui/widgets/calibration_result_view.h"
#include "ui/widgets/imgui_colour.h"

namespace lmc::ui {
namespace {

const ImVec4 kWarningRed(1.0F, 0.38F, 0.33F, 1.0F);
const ImVec4 kGood(0.55F, 0.9F, 0.55F, 1.0F);

// Where the file browsers open: the calibration trials' folder once something was recorded there,
// else the sessions folder, else the working folder (a browser on a missing folder lists nothing).
std::filesystem::path browse_start() {
  std::error_code ec;
  for (const auto& dir : {sessions_dir() / "calibration", sessions_dir()}) {
    if (std::filesystem::is_directory(dir, ec)) return dir;
  }
  return std::filesystem::current_path(ec);
}

}  // namespace

DevicesCalibratePanel::DevicesCalibratePanel(StatusSink& status, WorkbenchContext& context)
    : status_(status), layout_(context.layout()), step_(context.rig()) {}

void DevicesCalibratePanel::report(const std::string& text, bool is_error) {
  status_.set_status("Calibrate: " + text, is_error);
}

void DevicesCalibratePanel::update() {
  step_.update();
  step_.notice_layout(layout_.editor() != nullptr ? layout_.editor()->committed() : layout_.get());
  if (step_.message() != last_message_) {
    last_message_ = step_.message();
    if (!last_message_.empty()) report(last_message_, step_.message_is_error());
  }
  ghosts_ = step_.ghosts();
}

void DevicesCalibratePanel::undo_shortcut() {
  if (step_.undo_apply(layout_.editor())) return;
  if (step_.stage() == CalibrationStage::kApplied) {
    report("the layout's last change is not the calibration: undo it in the Layout tab", true);
  }
}

void DevicesCalibratePanel::draw() {
  ImGui::TextUnformatted("Calibrate");
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Refines where every controller stands from a still, open hand held where the trials happen.\n"
        "Calibrate after setting up or moving the controllers, or when their hands drift apart here.\n"
        "Same as: lmc calibrate TRIAL [--vicon FILE [--anchor-to-layout]] --layout L -o OUT.json");
  }
  switch (step_.stage()) {
    case CalibrationStage::kIdle:
      draw_start();
      break;
    case CalibrationStage::kRecording:
    case CalibrationStage::kCalibrating:
      draw_progress();
      break;
    case CalibrationStage::kResult:
    case CalibrationStage::kApplied:
      draw_result();
      break;
  }
  if (const auto chosen = trial_browser_.draw()) {
    CalibrationSettings settings;
    settings.vicon = vicon_;
    settings.anchor_to_layout = anchor_to_layout_;
    // A recorded trial is calibrated against the layout open now: the one it was recorded with.
    const Layout& layout = layout_.get();
    if (const std::string err = step_.calibrate_file(*chosen, layout, settings); !err.empty()) report(err, true);
  }
  if (const auto chosen = save_browser_.draw()) {
    if (const std::string err = step_.save(*chosen); !err.empty()) {
      report(err, true);
    } else {
      report("saved the calibrated layout to " + chosen->string(), false);
    }
  }
}

void DevicesCalibratePanel::draw_start() {
  ImGui::SetNextItemWidth(-1);
  ImGui::InputTextWithHint("##vicon", "Vicon file of the trial (.trc), optional", vicon_, sizeof vicon_);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "With a Vicon file each controller is fitted to the Vicon markers;\nwithout, the controllers are fitted to "
        "each other");
  ImGui::BeginDisabled(vicon_[0] == '\0');
  ImGui::Checkbox("anchor to layout", &anchor_to_layout_);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip(
        "With Vicon: keep the layout's world frame and take only where the controllers stand relative\n"
        "to each other from Vicon (when the Vicon origin is not the layout's origin)");
  }
  CalibrationSettings settings;
  settings.vicon = vicon_;
  settings.anchor_to_layout = anchor_to_layout_;
  if (ImGui::Button("Record 5 s still hand")) {
    const std::string err = step_.record(sessions_dir() / "calibration", settings);
    if (!err.empty()) report(err, true);
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Hold one open hand still where the trials happen, seen by every controller, for 5 s");
  }
  ImGui::SameLine();
  if (ImGui::Button("Calibrate from a recorded trial...")) {
    trial_browser_.open(FileBrowser::Mode::kOpen, browse_start());
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "An LMC recording of a still hand (e.g. LMC_Calibration.raw.txt), recorded with the layout open now");
  }
  if (!step_.message().empty()) {
    if (step_.message_is_error())
      ImGui::TextColored(kWarningRed, "%s", step_.message().c_str());
    else
      ImGui::TextDisabled("%s", step_.message().c_str());
  }
}

void DevicesCalibratePanel::draw_progress() {
  const bool recording = step_.stage() == CalibrationStage::kRecording;
  const float cancel_w = ImGui::CalcTextSize("Cancel").x + ImGui::GetStyle().FramePadding.x * 2;
  const float bar_w = ImGui::GetContentRegionAvail().x - cancel_w - ImGui::GetStyle().ItemSpacing.x;
  const std::string text = step_.activity();
  ImGui::ProgressBar(recording ? static_cast<float>(step_.recording_fraction()) : 1.0F, ImVec2(bar_w, 0),
                     recording ? "" : "calibrating");
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) step_.cancel();
  ImGui::TextWrapped("%s", text.c_str());
}

void DevicesCalibratePanel::draw_result() {
  const auto outcome = step_.outcome();
  if (!outcome) return;
  draw_calibration_result(outcome->trial, outcome->result, outcome->file_warnings, outcome->notes);

  if (step_.stage() == CalibrationStage::kResult) {
    if (ImGui::Button("Apply")) {
      const ActionResult a = step_.apply(layout_.editor());
      if (!a) report(a.error, true);
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Write the corrections into the layout as one undo step (Ctrl+Z undoes it)");
  } else {
    ImGui::TextColored(kGood, "Applied to layout '%s'.", layout_.get().name.c_str());
    if (ImGui::Button("Undo apply")) undo_shortcut();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Ctrl+Z");
  }
  ImGui::SameLine();
  if (ImGui::Button("Save layout...")) {
    save_browser_.open(FileBrowser::Mode::kSave, browse_start(), step_.suggested_file_name());
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Write the calibrated layout (its description names the trial and the date) to a file");
  }
  ImGui::SameLine();
  if (ImGui::Button(step_.stage() == CalibrationStage::kResult ? "Discard" : "Done")) step_.discard();
}

}  // namespace lmc::ui
