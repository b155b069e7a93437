#pragma once
// The ray-traced labels of one controller and finger as runs on the time axis, for the Review
// tab's label strips: consecutive frames with the same label become one run, so a strip
// draws a few rectangles instead of one per frame, and every gap in a curve lines up with the run
// that explains it. A run covers its samples plus half a step on each side.
#include <cstdint>
#include <span>
#include <vector>

namespace lmc::ui {

struct LabelRun {
  double x_from = 0, x_to = 0;
  std::int8_t label = -1;  // 1 seen, 0 internal model, −1 no hand
};

// `x` ascending, same length as `labels`. Only runs overlapping [view_lo, view_hi] are returned.
std::vector<LabelRun> label_runs(std::span<const double> x, std::span<const std::int8_t> labels, double view_lo,
                                 double view_hi);

}  // namespace lmc::ui
