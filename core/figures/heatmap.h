#pragma once
// A plain description of a heatmap: a grid of cells, rows × columns, each a value in [0, 1] or
// missing, coloured on one sequential scale (colour_scale.h) with a legend bar. Several panels
// may share the rows, columns and scale (e.g. "seen by ≥ 1" above "seen by ≥ 2"), stacked top to
// bottom, so their colours compare directly. Like Figure (figure.h) it is only data: the SVG
// writer (heatmap_svg.h), the CSV (figure_csv.h) and the sidecar (export_sidecar.h) read it.
#include <string>
#include <vector>

namespace lmc {

struct HeatmapPanel {
  std::string title;           // above the panel's cells; may be empty
  std::vector<double> values;  // row-major, rows × columns; NaN (or ±inf, or absent) = no data
};

enum class HeatmapValueText { none, percent, fraction };

struct Heatmap {
  std::string title;
  std::vector<std::string> rows;     // labels, top to bottom
  std::vector<std::string> columns;  // labels, left to right
  // Optional, one per column: consecutive columns with the same group share a header under
  // their labels ("palm down" over five motions). Empty: no group headers.
  std::vector<std::string> column_groups;
  std::string row_title, column_title;  // what the rows and columns are ("finger", "pose")
  std::string scale_label;              // what the colour means, beside the legend bar
  // What is written in each cell (and on the legend's ticks): nothing, "87 %", or "0.87". Cells
  // too small for the text get none.
  HeatmapValueText value_text = HeatmapValueText::percent;
  std::vector<HeatmapPanel> panels;
  std::vector<std::string> notes;  // short lines under the heatmap

  // The value at (row, column) of panel `p`; NaN when absent.
  double at(size_t p, size_t row, size_t column) const;
  // Whether any cell of any panel has no data (the legend then explains the hatched cell).
  bool has_missing() const;
};

}  // namespace lmc
