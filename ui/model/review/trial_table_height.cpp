#include "ui/model/review/trial_table_height.h"

#include <algorithm>

namespace lmc::ui {

float trial_table_height(float available_px, float row_px, std::size_t rows, float dragged_px) {
  // A table's frame adds a little below the last row; without it the last row shows a scrollbar.
  const float padding_px = 0.25F * row_px;
  const auto height_of = [&](std::size_t n) { return static_cast<float>(n + 1) * row_px + padding_px; };
  const float needed = height_of(rows);
  const float lowest = std::min(needed, height_of(kTrialTableMinRows));
  const float highest = std::max(lowest, std::min(needed, kTrialTableMaxShare * available_px));
  const float wanted = dragged_px > 0.0F ? dragged_px : kTrialTableShare * available_px;
  return std::clamp(wanted, lowest, highest);
}

}  // namespace lmc::ui
