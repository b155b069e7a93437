// The Review tab's trial table height: rows a user can compare at 1280 × 800, never more than the
// rows need, and a dragged splitter kept within limits.
#include "ui/model/review/trial_table_height.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lmc::ui {
namespace trial_table_height_test {  // named: test files share unity batches

// Whole data rows visible below the header in a table this tall.
int rows_shown(float height_px, float row_px) {
  return static_cast<int>(std::floor(height_px / row_px)) - 1;
}

// At 1280 × 800 with ImGui's 13 px font the table starts about 135 px down and 20 px of status
// line are below the tab: about 645 px remain; one row is 17 px.
constexpr float kRowPx = 17.0F;
constexpr float kAvailableAt1280x800 = 645.0F;

TEST(TrialTableHeight, ShowsNineRowsOrMoreAt1280x800) {
  const float h = trial_table_height(kAvailableAt1280x800, kRowPx, 32);
  EXPECT_GE(rows_shown(h, kRowPx), 9);        // a fifth of the height showed 7
  EXPECT_LE(h, 0.5F * kAvailableAt1280x800);  // the views below keep most of the height
}

TEST(TrialTableHeight, NeverTallerThanItsRows) {
  const float h = trial_table_height(kAvailableAt1280x800, kRowPx, 3);
  EXPECT_EQ(rows_shown(h, kRowPx), 3);
  EXPECT_LT(h, 5.0F * kRowPx);
}

TEST(TrialTableHeight, ADraggedSplitterStaysWithinLimits) {
  EXPECT_FLOAT_EQ(trial_table_height(kAvailableAt1280x800, kRowPx, 32, 300.0F), 300.0F);
  // Dragged up to nothing: still the header and four rows.
  EXPECT_EQ(rows_shown(trial_table_height(kAvailableAt1280x800, kRowPx, 32, 10.0F), kRowPx),
            static_cast<int>(kTrialTableMinRows));
  // Dragged down past the views: at most 70 % of the height.
  EXPECT_FLOAT_EQ(trial_table_height(kAvailableAt1280x800, kRowPx, 32, 2000.0F),
                  kTrialTableMaxShare * kAvailableAt1280x800);
  // With few rows the drag cannot open empty space below them.
  EXPECT_EQ(rows_shown(trial_table_height(kAvailableAt1280x800, kRowPx, 6, 400.0F), kRowPx), 6);
}

}  // namespace trial_table_height_test
}  // namespace lmc::ui
