#include "ui/tabs/record/subject_screen_controls_panel.h"

#include "ui/widgets/palette.h"

#include <imgui.h>

#include <string>

namespace lmc::ui {

void SubjectScreenControlsPanel::draw() {
  anchors_.clear();  // only what this frame drew
  SubjectScreenLink& link = link_;
  if (ImGui::SmallButton(link.open ? "Close subject screen (F2)" : "Subject screen (F2)")) link.open = !link.open;
  anchors_.remember("toggle");
  ImGui::SameLine();
  const int n = static_cast<int>(link.monitors.size());
  // Where it is or would open (a second monitor when there is one, else the operator's pick).
  const int shown_monitor = link.placed_monitor >= 0 && link.placed_monitor < n ? link.placed_monitor : -1;
  ImGui::SetNextItemWidth(230);
  // Closed, the short label (Windows names monitors at length); open, the list with the names.
  const bool has_short = shown_monitor >= 0 && static_cast<size_t>(shown_monitor) < link.monitor_shorts.size();
  const std::string& preview = has_short            ? link.monitor_shorts[static_cast<size_t>(shown_monitor)]
                               : shown_monitor >= 0 ? link.monitors[static_cast<size_t>(shown_monitor)]
                                                    : std::string("no monitor");
  if (ImGui::BeginCombo("##monitor", preview.c_str())) {
    for (int i = 0; i < n; ++i)
      if (ImGui::Selectable(link.monitors[static_cast<size_t>(i)].c_str(), i == shown_monitor)) link.monitor = i;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  // Shows what the window will be (the bench's default until the operator chooses).
  bool windowed = subject_screen_windowed(link);
  // Full screen only on a second monitor: with one it would hide this window.
  ImGui::BeginDisabled(n < 2);
  if (ImGui::Checkbox("windowed", &windowed)) link.windowed = windowed;
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(n < 2 ? "One monitor: the subject screen is a window beside this one (it opens where you last "
                              "left it); full screen needs a second monitor."
                            : "Off: the subject screen fills the chosen monitor. On: a plain window.");
  if (!link.problem.empty())
    ImGui::TextColored(palette::kError, "%s", link.problem.c_str());  // own line: it must be read whole
}

}  // namespace lmc::ui
