#include "ui/widgets/split_panels.h"

#include <algorithm>

namespace lmc::ui {

void SplitPanels::draw(const std::function<void()>& left, const std::function<void()>& right) {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float splitter_w = options_.splitter_width;
  right_width_ =
      std::clamp(right_width_, options_.min_right, std::max(options_.min_right, avail.x - options_.min_left));
  // On a window too narrow for both minimums the left side still keeps a usable strip.
  const float left_w = std::max(200.0f, avail.x - right_width_ - splitter_w);

  ImGui::BeginChild("##left", ImVec2(left_w, avail.y), false, options_.left_flags);
  left();
  ImGui::EndChild();

  ImGui::SameLine(0, 0);
  ImGui::InvisibleButton("##splitter", ImVec2(splitter_w, avail.y));
  if (ImGui::IsItemActive()) right_width_ -= ImGui::GetIO().MouseDelta.x;
  if (ImGui::IsItemHovered() || ImGui::IsItemActive()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
  ImGui::SameLine(0, 0);

  ImGui::BeginChild("##right", ImVec2(0, avail.y), false, options_.right_flags);
  right();
  ImGui::EndChild();
}

}  // namespace lmc::ui
