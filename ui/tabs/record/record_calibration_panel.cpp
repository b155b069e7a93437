#include "ui/tabs/record/record_calibration_panel.h"

#include <imgui.h>

#include <algorithm>

#include "ui/widgets/calibration_result_view.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
namespace {

bool calibration_big_button(const char* label, ImVec4 colour) {
  ImGui::PushStyleColor(ImGuiCol_Button, colour);
  ImGui::SetWindowFontScale(1.3F);
  const bool pressed = ImGui::Button(label, ImVec2(300, 48));
  ImGui::SetWindowFontScale(1.0F);
  ImGui::PopStyleColor();
  return pressed;
}

}  // namespace

void RecordCalibrationPanel::keep_nominal(TrialPanelAction& action) {
  ImGui::PushItemWidth(360);
  ImGui::InputTextWithHint("##nominal_reason", "why keep the nominal layout (journaled)", nominal_reason_,
                           sizeof nominal_reason_);
  ImGui::PopItemWidth();
  ImGui::SameLine();
  if (ImGui::Button("Keep nominal layout")) action = TrialPanelAction::kKeepNominal;
  anchors_.remember("keep_nominal");
}

TrialPanelAction RecordCalibrationPanel::draw() {
  anchors_.clear();  // only what this frame drew
  const RecordState& model = *model_;
  TrialPanelAction action = TrialPanelAction::kNone;
  const auto& step = *model.state().protocol.calibration;
  const Layout* layout = model.current_layout();
  ImGui::SetWindowFontScale(1.3F);
  ImGui::Text("Calibrate layout '%s' from the hand", layout ? layout->name.c_str() : "?");
  ImGui::SetWindowFontScale(1.0F);
  ImGui::TextWrapped("Operator: %s", step.operator_cue.c_str());
  ImGui::TextWrapped("Subject: %s", step.subject_cue.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped(
      "Before the block's first trial: a %.0f s still-hand trial, from which the controllers are "
      "calibrated against Vicon when the trial's Vicon file is found, else against each other. Nothing "
      "changes until you apply it.",
      step.duration_s);
  ImGui::PopStyleColor();
  ImGui::Spacing();

  if (model.calibrating()) {
    const auto& live = model.live();
    const double done = live ? live->recording_s : 0.0;
    ImGui::Text("Recording the calibration trial: %.1f s of %.0f s", done, step.duration_s);
    ImGui::ProgressBar(static_cast<float>(std::clamp(done / step.duration_s, 0.0, 1.0)), ImVec2(360, 0));
    if (calibration_big_button("Stop  [Space]", palette::kButtonStop)) action = TrialPanelAction::kStop;
    return action;
  }
  const auto& pending = model.pending_calibration();
  if (pending) {
    if (pending->ok()) {
      draw_calibration_result(pending->trial_name, pending->fit->result, pending->fit->file_warnings,
                              pending->fit->notes);
      ImGui::Spacing();
      if (calibration_big_button("Apply  [Enter]", palette::kButtonGo)) action = TrialPanelAction::kApplyCalibration;
      anchors_.remember("apply_calibration");
      ImGui::SameLine();
    } else {
      ImGui::TextColored(palette::kError, "%s: %s", pending->trial_name.c_str(), pending->failure.c_str());
    }
    if (ImGui::Button("Calibrate again  [R]", ImVec2(200, 48))) action = TrialPanelAction::kCalibrate;
    anchors_.remember("calibrate_again");
    keep_nominal(action);
    return action;
  }
  if (calibration_big_button("Record calibration  [Space]", palette::kButtonAction))
    action = TrialPanelAction::kCalibrate;
  anchors_.remember("calibrate");
  ImGui::Spacing();
  keep_nominal(action);
  return action;
}

}  // namespace lmc::ui
