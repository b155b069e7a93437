#pragma once
// How tall the Review tab's trial table is: the table and the views below it (the trial against
// Vicon, the agreement table and plot) share the tab's height, and at 1280 × 800 a fifth of it was
// 7 rows. The rule gives the table a little over a quarter by default (9 rows there: more would
// push the agreement plot off the bottom), no more than its rows need, and lets the operator drag
// the splitter below it within limits that keep a few rows and the views usable.
#include <cstddef>

namespace lmc::ui {

// Share of the height below the filters the table takes unless dragged.
inline constexpr float kTrialTableShare = 0.27F;
// Never fewer rows than this (when there are as many), never more than this share of the height.
inline constexpr std::size_t kTrialTableMinRows = 4;
inline constexpr float kTrialTableMaxShare = 0.70F;

// The table's height in pixels. `available_px`: from the table's top to the bottom of the tab;
// `row_px`: one row's height (the header is one more); `rows`: rows the filters let through;
// `dragged_px` > 0: the height the operator dragged the splitter to (kept within the limits).
float trial_table_height(float available_px, float row_px, std::size_t rows, float dragged_px = 0.0F);

}  // namespace lmc::ui
