#include "ui/tabs/record/record_trial_list_panel.h"

#include <imgui.h>

#include <string>

#include "ui/tabs/record/record_colours.h"

namespace lmc::ui {

int draw_record_trial_list(const session::SessionState& state, int current, int recording) {
  int clicked = -1;
  std::string block;
  for (const auto& t : state.trials) {
    if (t.plan.layout_key != block) {
      block = t.plan.layout_key;
      ImGui::Spacing();
      ImGui::TextDisabled("Layout %s", block.c_str());
      ImGui::Separator();
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
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s, %zu attempt(s)", look.word, t.attempts.size());
    if (t.plan.index == current && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY(0.3F);
    ImGui::PopID();
  }
  return clicked;
}

}  // namespace lmc::ui
