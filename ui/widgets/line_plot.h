#pragma once
// A small line plot (no ImPlot in Debian): one series against its index, optional log10 y axis, values shown with 4 significant digits,
// min/max labels, hover readout. Non-finite or (on a log axis) non-positive values are skipped.
#include <span>
#include <string>

namespace lmc::ui {

struct LinePlotOptions {
  bool log_y = false;
  float height_px = 120;
  const char* x_label = "iteration";
  int x_extent = 0;  // draw the x axis up to this many points (e.g. the planned iterations)
};

void draw_line_plot(const char* id, std::span<const double> values, const LinePlotOptions& options);

}  // namespace lmc::ui
