#pragma once
// A heatmap (heatmap.h) as a standalone SVG 1.1 document, in the same style as the plots
// (svg_writer.h): title on top, row labels to the left of the cells, column labels (wrapped, or
// turned upright when a word is wider than its cell) and group headers under the bottom panel, a
// legend bar on the right saying what the colour means, notes under everything. A cell with no
// data is hatched grey and the legend says so. Deterministic bytes, C-locale numbers.
//
// Elements a reader (or a test) can pick out: <rect class="cell"> per cell, with class
// "cell no-data" when the value is missing; <text class="cell-value"> per written value;
// <rect class="legend-bar">.
#include <string>

#include "core/figures/heatmap.h"

namespace lmc {

// Sizes below 240 × 160 px are raised to it; the cells share what the labels and legend leave.
std::string to_svg(const Heatmap& heatmap, int width_px = 800, int height_px = 520);

}  // namespace lmc
