#pragma once
// A figure as a standalone SVG 1.1 document: what the Review tab's "export figure" and
// `lmc figures` write, readable by any browser or vector editor and pasteable into a paper.
// Everything is drawn from the Figure alone (no fonts measured, no clock, no random ids), so the
// same figure always gives the same bytes; numbers are written in the C locale.
#include <string>

#include "core/figures/figure.h"

namespace lmc {

// Sizes below 240 × 160 px are raised to it (smaller leaves no room for the plot).
std::string to_svg(const Figure& figure, int width_px = 800, int height_px = 500);

// The panels stacked top to bottom, equally tall, on one x range; x tick labels and the x axis
// label only under the bottom panel.
std::string to_svg(const FigureGrid& grid, int width_px = 800, int height_px = 800);

}  // namespace lmc
