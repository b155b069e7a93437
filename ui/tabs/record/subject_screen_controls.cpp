#include "ui/tabs/record/subject_screen_controls.h"

#include <imgui.h>

namespace lmc::ui {

void draw_subject_screen_controls(SubjectScreenLink& link) {
  if (ImGui::SmallButton(link.open ? "Close subject screen (F2)" : "Subject screen (F2)")) link.open = !link.open;
  ImGui::SameLine();
  const int n = static_cast<int>(link.monitors.size());
  const int shown_monitor = link.monitor >= 0 && link.monitor < n ? link.monitor : n - 1;
  ImGui::SetNextItemWidth(230);
  if (ImGui::BeginCombo("##monitor", shown_monitor >= 0 ? link.monitors[static_cast<size_t>(shown_monitor)].c_str() : "no monitor")) {
    for (int i = 0; i < n; ++i)
      if (ImGui::Selectable(link.monitors[static_cast<size_t>(i)].c_str(), i == shown_monitor)) link.monitor = i;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::Checkbox("windowed", &link.windowed);
  if (!link.problem.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0F, 0.4F, 0.35F, 1.0F), "%s", link.problem.c_str());
  } else if (link.open && n == 1 && !link.windowed) {
    ImGui::SameLine();
    ImGui::TextDisabled("(covers this monitor)");
  }
}

}  // namespace lmc::ui
