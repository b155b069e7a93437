#pragma once
// A plain description of one chart (and of a stack of charts sharing x), independent of how it is
// drawn: the SVG writer, the CSV of the data behind it and a future screen view all read the same
// value, so an exported figure cannot show anything the CSV lacks.
#include <optional>
#include <string>
#include <vector>

#include "core/figures/palette.h"

namespace lmc {

struct AxisRange {
  double lo = 0.0, hi = 1.0;
};

struct Axis {
  std::string label;               // "time"
  std::string unit;                // "s"; empty for a dimensionless quantity
  std::optional<AxisRange> range;  // fixed; else fitted to the finite data with a small margin
};

enum class SeriesStyle { line, points, line_and_points };

// x[i], y[i] is one sample. A NaN or ±inf in either is a missing sample: a line breaks there into
// separate pieces (never drawn to 0) and the CSV leaves the cell empty.
struct Series {
  std::string name;           // in the legend and the CSV; a series with no name has no legend entry
  std::optional<Rgb> colour;  // unset: the palette colour of the series' position (palette.h)
  SeriesStyle style = SeriesStyle::line;
  std::vector<double> x, y;
  bool shade_gaps = false;  // a faint band over each run of missing samples between two present ones
};

enum class Dash { solid, dashed, dotted };

// A horizontal line across the plot, e.g. a Bland–Altman bias and its limits of agreement.
struct ReferenceLine {
  double y = 0.0;
  std::string label;  // written beside the line, outside the plot area
  Dash dash = Dash::dashed;
  Rgb colour = {80, 80, 80};
};

struct Figure {
  std::string title;
  Axis x, y;
  std::vector<Series> series;
  std::vector<ReferenceLine> references;
  std::vector<std::string> notes;  // short lines of text written under the chart
};

// Several charts stacked vertically on one x axis (stacked time plots). The panels' own x axes
// are ignored: `x` is shared, labelled once under the bottom panel.
struct FigureGrid {
  std::string title;
  Axis x;
  std::vector<Figure> panels;
  std::vector<std::string> notes;
};

// The colour series `index` of a figure is drawn in.
Rgb colour_of(const Series& s, std::size_t index);

// The ranges a figure is drawn over: the axis' fixed range, else the finite samples' extent
// (reference lines included on y) widened by a small margin; a single value gets ±1 and no data
// at all gives [0, 1]. x covers every finite x, so a gap at either end stays in view.
AxisRange x_range(const Figure& f);
AxisRange y_range(const Figure& f);
AxisRange x_range(const FigureGrid& g);

}  // namespace lmc
