#include "ui/tabs/record/record_trial_list_panel.h"

#include <imgui.h>

#include <string>

#include "ui/tabs/record/record_colours.h"

namespace lmc::ui {

void RecordTrialListPanel::draw() {
  anchors_.clear();  // only what this frame drew
  RecordState& model = *model_;
  const SessionState& state = model.state();
  const int current = model.current_trial();
  const int recording = model.recording_trial();
  int clicked = -1;
  // Grouped as the protocol records them: layout, then palm pose and motion (a sub-heading each time
  // either changes, so a counterbalanced order still reads correctly).
  std::string block;
  int pose = -1, motion = -1;
  for (const auto& t : state.trials) {
    if (t.plan.layout_key != block) {
      block = t.plan.layout_key;
      pose = motion = -1;
      ImGui::Spacing();
      ImGui::TextDisabled("Layout %s", block.c_str());
      ImGui::Separator();
    }
    if (t.plan.pose != pose || t.plan.trial_type != motion) {
      pose = t.plan.pose;
      motion = t.plan.trial_type;
      const auto& poses = state.protocol.poses;
      const auto& types = state.protocol.trial_types;
      const bool known = pose >= 0 && static_cast<size_t>(pose) < poses.size() && motion >= 0 &&
                         static_cast<size_t>(motion) < types.size();
      if (known) {
        ImGui::TextDisabled("  %s, %s", poses[static_cast<size_t>(pose)].key.c_str(),
                            types[static_cast<size_t>(motion)].key.c_str());
      }
    }
    const bool is_recording = t.plan.index == recording;
    const StatusLook look = trial_status_look(t, is_recording);
    ImGui::PushID(t.plan.index);
    ImGui::PushStyleColor(ImGuiCol_Text, look.colour);
    ImGui::TextUnformatted(look.icon);
    ImGui::PopStyleColor();
    ImGui::SameLine();
    const std::string label = t.plan.name + (t.attempts.size() > 1 ? "  ×" + std::to_string(t.attempts.size()) : "");
    if (ImGui::Selectable(label.c_str(), t.plan.index == current)) clicked = t.plan.index;
    anchors_.remember("trial." + std::to_string(t.plan.index));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s, %zu attempt(s)", look.word, t.attempts.size());
    if (t.plan.index == current && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY(0.3F);
    ImGui::PopID();
  }
  if (clicked >= 0 && !model.busy()) model.select(clicked);
}

}  // namespace lmc::ui
