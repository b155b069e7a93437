#include "ui/tabs/layout/heatmap_panel.h"

#include <imgui.h>

#include <string>

#include "ui/widgets/colour_legend.h"
#include "ui/widgets/palette.h"
#include "ui/widgets/progress_row.h"

namespace lmc::ui {

void HeatmapPanel::draw() {
  LayoutState& s = *state_;
  DisplaySettings& d = s.display;
  ImGui::Checkbox("Show the heatmap on the table", &d.show_heatmap);
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled(
      "Each cell: the selected controller standing there (same height and orientation). Share of the "
      "pose set's frames in which the finger would be visible, or the frames it would add because no "
      "other controller sees the finger.");
  ImGui::PopTextWrapPos();
  if (s.selected() < 0) {
    ImGui::TextColored(palette::kWarning, "Select a controller to sweep.");
  } else {
    ImGui::Text("Controller: %s", s.layout().devices[static_cast<size_t>(s.selected())].slot.c_str());
  }
  const char* fingers[] = {"all five", "thumb", "index", "middle", "ring", "pinky"};
  int f = d.heatmap_finger + 1;
  ImGui::SetNextItemWidth(140);
  if (ImGui::Combo("Finger", &f, fingers, 6)) d.heatmap_finger = f - 1;
  int mode = static_cast<int>(d.heatmap_mode);
  ImGui::RadioButton("frames visible", &mode, 0);
  ImGui::SameLine();
  ImGui::RadioButton("frames added (seen by no other)", &mode, 1);
  d.heatmap_mode = static_cast<HeatmapMode>(mode);
  ImGui::SetNextItemWidth(140);
  ImGui::SliderInt("Grid cells per side", &d.heatmap_cells, 8, 96);
  float extent = static_cast<float>(d.heatmap_half_extent_mm);
  ImGui::SetNextItemWidth(140);
  if (ImGui::SliderFloat("Half extent", &extent, 100.0f, 1000.0f, "±%.0f mm")) d.heatmap_half_extent_mm = extent;
  ImGui::Checkbox("Fixed scale 0-100 % (comparable between fingers)", &d.heatmap_fixed_range);

  ImGui::Spacing();
  draw_colour_bar(s.heatmap_range(), std::min(300.0f, ImGui::GetContentRegionAvail().x), 100.0, 0, " %");
  const HeatmapGridPtr g = s.heatmap().latest();
  if (g) {
    ImGui::TextDisabled("data range %.1f - %.1f %% · %d × %d cells%s", g->data_min * 100, g->data_max * 100, g->nx,
                        g->nz, g->fine ? "" : " (preview)");
  }
  if (s.heatmap().computing()) {
    draw_progress_row("heatmap", s.heatmap().fraction(), s.heatmap().stage(), 0.0, std::nullopt, false);
  }
  if (!s.heatmap().error().empty()) ImGui::TextColored(palette::kError, "%s", s.heatmap().error().c_str());
}

}  // namespace lmc::ui
