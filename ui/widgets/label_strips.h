#pragma once
// Under the Review tab's plots: one thin strip per controller × finger coloured by its ray-traced
// label (seen, internal model, no hand) on the plots' shared x range, so a gap or a jump in a curve
// shows which controller lost which finger at that moment. Hovering names the strip,
// the label and the time; the shared cursor is drawn through every strip.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ui/model/plot/linked_x_range.h"

namespace lmc::ui {

struct LabelStrip {
  std::string group;  // "LMC1": written once in the gutter for consecutive strips
  std::string name;   // "index": the tooltip's words
  std::span<const std::int8_t> labels;
};

// Strips share `x` (ascending seconds). Draws at the cursor with the full available width.
void draw_label_strips(const char* id, std::span<const double> x, const std::vector<LabelStrip>& strips,
                       LinkedXRange& range, float strip_height_px = 5.0F);

// The pixels draw_label_strips takes for these strips (strips, gaps, and a wider gap between groups),
// so a view can keep room for them below its plots.
float label_strips_height(const std::vector<LabelStrip>& strips, float strip_height_px = 5.0F);

// The legend of the three label colours, on one line.
void draw_label_legend();

}  // namespace lmc::ui
