#include "ui/widgets/plot_frame.h"

#include "ui/widgets/palette.h"

#include <algorithm>

namespace lmc::ui {

PlotFrame begin_plot_frame(float height_px, float min_width_px) {
  PlotFrame f;
  f.width = std::max(min_width_px, ImGui::GetContentRegionAvail().x);
  f.p0 = ImGui::GetCursorScreenPos();
  f.p1 = ImVec2(f.p0.x + f.width, f.p0.y + height_px);
  f.draw = ImGui::GetWindowDrawList();
  f.draw->AddRectFilled(f.p0, f.p1, palette::kPanelBackground, 3.0F);
  f.draw->AddRect(f.p0, f.p1, palette::kPanelBorder, 3.0F);
  ImGui::InvisibleButton("plot", ImVec2(f.width, height_px));
  f.hovered = ImGui::IsItemHovered();
  return f;
}

void draw_y_range_labels(const PlotFrame& frame, const char* top, const char* bottom) {
  const ImU32 colour = palette::kPlotTickText;
  frame.draw->AddText(ImVec2(frame.p0.x + 4, frame.p0.y + 2), colour, top);
  frame.draw->AddText(ImVec2(frame.p0.x + 4, frame.p1.y - ImGui::GetTextLineHeight() - 2), colour, bottom);
}

}  // namespace lmc::ui
