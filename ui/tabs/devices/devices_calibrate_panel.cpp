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

void DevicesCalibratePanel::draw() {
  CalibrationStep& step = state_->calibration();
  ImGui::TextUnformatted("Calibrate");
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Refines where every controller stands from a still, open hand held where the trials happen.\n"
        "Calibrate after setting up or moving the controllers, or when their hands drift apart here.\n"
        "Same as: lmc calibrate TRIAL [--vicon FILE [--anchor-to-layout]] --layout L -o OUT.json");
  }
  switch (step.stage()) {
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
    const Layout& layout = state_->shared_layout().get();
    if (const std::string err = step.calibrate_file(*chosen, layout, settings); !err.empty())
      state_->report_calibration(err, true);
  }
  if (const auto chosen = save_browser_.draw()) {
    if (const std::string err = step.save(*chosen); !err.empty()) {
      state_->report_calibration(err, true);
    } else {
      state_->report_calibration("saved the calibrated layout to " + chosen->string(), false);
    }
  }
}

void DevicesCalibratePanel::draw_start() {
  CalibrationStep& step = state_->calibration();
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
    const std::string err = step.record(sessions_dir() / "calibration", settings);
    if (!err.empty()) state_->report_calibration(err, true);
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Hold one open hand still where the trials happen, seen by every controller, for 5 s");
  }
  // Beside the first button where it fits, else under it (a 1024-pixel window).
  constexpr const char* kFromTrial = "Calibrate from a recorded trial...";
  ImGui::SameLine();
  if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(kFromTrial).x + 2 * ImGui::GetStyle().FramePadding.x)
    ImGui::NewLine();
  if (ImGui::Button(kFromTrial)) {
    trial_browser_.open(FileBrowser::Mode::kOpen, browse_start());
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "An LMC recording of a still hand (e.g. LMC_Calibration.raw.txt), recorded with the layout open now");
  }
  if (!step.message().empty()) {
    if (step.message_is_error())
      ImGui::TextColored(kWarningRed, "%s", step.message().c_str());
    else
      ImGui::TextDisabled("%s", step.message().c_str());
  }
}

void DevicesCalibratePanel::draw_progress() {
  CalibrationStep& step = state_->calibration();
  const bool recording = step.stage() == CalibrationStage::kRecording;
  const float cancel_w = ImGui::CalcTextSize("Cancel").x + ImGui::GetStyle().FramePadding.x * 2;
  const float bar_w = ImGui::GetContentRegionAvail().x - cancel_w - ImGui::GetStyle().ItemSpacing.x;
  const std::string text = step.activity();
  ImGui::ProgressBar(recording ? static_cast<float>(step.recording_fraction()) : 1.0F, ImVec2(bar_w, 0),
                     recording ? "" : "calibrating");
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) step.cancel();
  ImGui::TextWrapped("%s", text.c_str());
}

void DevicesCalibratePanel::draw_result() {
  CalibrationStep& step = state_->calibration();
  CurrentLayout& shared = state_->shared_layout();
  const auto outcome = step.outcome();
  if (!outcome) return;
  draw_calibration_result(outcome->trial, outcome->result, outcome->file_warnings, outcome->notes);

  if (step.stage() == CalibrationStage::kResult) {
    if (ImGui::Button("Apply")) {
      const ActionResult a = step.apply(shared.editor());
      if (!a) state_->report_calibration(a.error, true);
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Write the corrections into the layout as one undo step (Ctrl+Z undoes it)");
  } else {
    ImGui::TextColored(kGood, "Applied to layout '%s'.", shared.get().name.c_str());
    if (ImGui::Button("Undo apply")) state_->undo_calibration();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Ctrl+Z");
  }
  ImGui::SameLine();
  if (ImGui::Button("Save layout...")) {
    save_browser_.open(FileBrowser::Mode::kSave, browse_start(), step.suggested_file_name());
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Write the calibrated layout (its description names the trial and the date) to a file");
  }
  ImGui::SameLine();
  if (ImGui::Button(step.stage() == CalibrationStage::kResult ? "Discard" : "Done")) step.discard();
}

}  // namespace lmc::ui
