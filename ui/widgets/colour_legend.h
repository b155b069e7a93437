#pragma once
// Colour legends (docs/architecture.md): a categorical legend lists every category with its swatch; a
// colour bar shows a sequential map with numbers at both ends and the middle.
#include <string>
#include <vector>

#include "ui/scene/colour_maps.h"

namespace lmc::ui {

struct LegendEntry {
  Rgba colour;
  std::string label;
};

// Swatches on one line (wrapping when the region is narrow).
void draw_categorical_legend(const std::vector<LegendEntry>& entries);
// A horizontal viridis bar of `width_px` with tick labels at lo, middle and hi of the display
// range: value × scale with `decimals` digits and a unit suffix (e.g. scale 100, unit " %").
void draw_colour_bar(const ColourRange& range, float width_px, double scale = 1.0, int decimals = 0,
                     const char* unit = "");

}  // namespace lmc::ui
