#pragma once
// The frame every small plot of ui/widgets draws first: a dark panel with a border that takes the
// full available width, an invisible button over it (so hovering and the ImGui id work), and the
// y range written at its top-left and bottom-left corners. One place, so the plots look alike.
#include <imgui.h>

#include "ui/widgets/palette.h"

namespace lmc::ui {

struct PlotFrame {
  ImDrawList* draw = nullptr;
  ImVec2 p0, p1;  // top-left and bottom-right corners in screen pixels
  float width = 0;
  bool hovered = false;
};

// Draws the panel at the cursor and advances the layout past it. Call inside the plot's PushID.
PlotFrame begin_plot_frame(float height_px, float min_width_px);

// The top and bottom values of the y axis, already formatted.
void draw_y_range_labels(const PlotFrame& frame, const char* top, const char* bottom);

}  // namespace lmc::ui
