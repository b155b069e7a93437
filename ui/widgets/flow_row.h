#pragma once
// Rows of controls that wrap instead of running off a narrow window (a 1024-pixel laptop screen):
// the next item goes beside the last when it fits, else at the start of the next line.
#include <imgui.h>

namespace lmc::ui {

// Call between two items, with the next item's width (checkbox_width() for a checkbox).
inline void same_line_or_wrap(float next_width, float spacing = -1.0f) {
  ImGui::SameLine(0.0f, spacing);
  if (ImGui::GetContentRegionAvail().x < next_width) ImGui::NewLine();
}

// The width ImGui gives a checkbox with this label.
inline float checkbox_width(const char* label) {
  return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
}

}  // namespace lmc::ui
