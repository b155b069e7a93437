#pragma once
// Round tick values for a plot axis (1, 2 or 5 times a power of ten), about `target` of them
// across [lo, hi], and the y range a plot shows: the visible samples' extent with a margin.
// Core's, so the screen plots (ui/model/plot/axis_ticks.h forwards here) and the exported
// figures (svg_writer) pick the same ticks.
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace lmc {

std::vector<double> nice_ticks(double lo, double hi, int target = 5);

// A tick's text with just enough decimals to tell it from its neighbours in `ticks` (nice_ticks'
// output): 0.25 steps give "0.25", 20 steps give "40"; C locale. The screen plots and the SVG
// label their axes alike.
std::string tick_label(double value, const std::vector<double>& ticks);

// A value read off an axis that spans [lo, hi] (a plot's cursor readout): as many decimals as
// resolve a hundredth of the span (a 0–12° axis: one; 86–88 mm: two), so a value that is zero to
// the axis reads "0.0", never "8.5e-07"; C locale, no sign on a rounded zero. Two decimals when the
// span is empty or not finite.
std::string value_label(double value, double lo, double hi);

// Min and max of the finite y whose x lies in [x_lo, x_hi] over every series given, widened by
// `margin` of its span (a flat series gets ±1); nullopt-like {0, 1} when nothing is visible.
std::pair<double, double> fit_y_range(std::span<const std::span<const double>> xs,
                                      std::span<const std::span<const double>> ys, double x_lo, double x_hi,
                                      double margin = 0.05);

}  // namespace lmc
