#pragma once
// A small plot of several series over time on one fixed y range, without zoom (series_plot.h is
// the full plot with linked zoom and a fitted y): the Record tab's verdict draws each controller's hand
// presence and finger visibility over the trial with it. Non-finite values leave a gap; hovering
// reads every series at that time.
#include <array>
#include <span>
#include <string>
#include <vector>

namespace lmc::ui {

struct TimelineSeries {
  std::string label;
  std::array<float, 3> rgb{1, 1, 1};  // 0..1
  std::span<const double> values;     // one per slice
  float thickness = 1.5F;
};

struct TimelinePlotOptions {
  double slice_s = 1.0;  // x: value k is at k·slice_s seconds
  double y_min = 0, y_max = 1;
  int y_decimals = 0;  // of the y range's labels
  float height_px = 90;
};

void draw_timeline_plot(const char* id, std::span<const TimelineSeries> series, const TimelinePlotOptions& options);

}  // namespace lmc::ui
