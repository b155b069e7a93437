#include "ui/scene/label_spreading.h"

#include <gtest/gtest.h>

namespace lmc::ui {
namespace label_spreading_test {

TEST(LabelSpreading, OverlappingLabelsMoveUpUntilClearAndTheFirstStays) {
  // "LMC1" and "LMC2" projected almost onto each other (default view).
  const std::vector<LabelBox> in = {{100, 200, 32, 13}, {110, 204, 32, 13}, {400, 50, 40, 13}};
  const auto out = spread_labels(in, 2.0f);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0].y, 200.0f);
  EXPECT_EQ(out[0].x, 100.0f);
  EXPECT_EQ(out[1].x, 110.0f) << "labels only move up";
  EXPECT_EQ(out[1].y, 200.0f - 13.0f - 2.0f);  // just above the first, 2 px apart
  EXPECT_LE(out[1].y + out[1].height, out[0].y);
  EXPECT_EQ(out[2].y, 50.0f) << "a label clear of the others does not move";
}

TEST(LabelSpreading, AThirdLabelClimbsPastBothAndStepsAreBounded) {
  const std::vector<LabelBox> stack = {{0, 100, 20, 10}, {0, 100, 20, 10}, {0, 100, 20, 10}};
  const auto out = spread_labels(stack, 0.0f);
  EXPECT_EQ(out[1].y, 90.0f);
  EXPECT_EQ(out[2].y, 80.0f);
  const auto capped = spread_labels(stack, 0.0f, 1);
  EXPECT_EQ(capped[2].y, 90.0f) << "one step allowed: still overlapping the second, but bounded";
}

}  // namespace label_spreading_test
}  // namespace lmc::ui
