#pragma once
// Drawing a long series into a plot a few hundred pixels wide: per pixel column, the
// smallest and largest finite y of the samples whose x falls in it. Drawn as a vertical bar per
// column joined to the next, it shows every spike a million samples hold, at the cost of one pass.
// Missing values are never bridged: a column whose samples are all NaN is a gap, and the line
// breaks there (and wherever a NaN sits between two columns' data); a column holding both data and
// NaN keeps its data and is marked as touching a gap.
#include <span>
#include <vector>

namespace lmc::ui {

struct PlotColumn {
  float y_min = 0, y_max = 0;
  float y_first = 0, y_last = 0;  // the column's first and last finite y, to join neighbours faithfully
  bool has_data = false;
  bool touches_gap = false;     // some sample in the column is NaN
  bool joins_previous = false;  // draw a line from the previous column's last y (no NaN in between)
};

// `x` ascending (NaN x not allowed), `y` the same length. Columns split [x_lo, x_hi] evenly (the
// last column includes x_hi); samples outside are skipped (found by binary search, so zoomed views cost what they
// show).
std::vector<PlotColumn> decimate_min_max(std::span<const double> x, std::span<const double> y, double x_lo, double x_hi,
                                         int columns);

}  // namespace lmc::ui
