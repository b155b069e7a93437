// Label runs for the Review tab's strips: consecutive equal labels merge, each run
// reaches half a step beyond its samples, and only runs in view come back.
#include <gtest/gtest.h>

#include <vector>

#include "ui/model/plot/label_runs.h"

namespace lmc::ui {
namespace label_runs_test {  // named: test files share unity batches

TEST(LabelRuns, MergesEqualNeighboursAndCoversHalfAStepEachSide) {
  const std::vector<double> x = {0.0, 0.1, 0.2, 0.3, 0.4};
  const std::vector<std::int8_t> l = {1, 1, 0, -1, -1};
  const auto runs = label_runs(x, l, -1.0, 1.0);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].label, 1);
  EXPECT_NEAR(runs[0].x_from, -0.05, 1e-12);
  EXPECT_NEAR(runs[0].x_to, 0.15, 1e-12);
  EXPECT_EQ(runs[1].label, 0);
  EXPECT_NEAR(runs[1].x_from, 0.15, 1e-12);
  EXPECT_NEAR(runs[1].x_to, 0.25, 1e-12);
  EXPECT_EQ(runs[2].label, -1);
  EXPECT_NEAR(runs[2].x_to, 0.45, 1e-12);
}

TEST(LabelRuns, OnlyRunsInViewAndNothingForNoSamples) {
  const std::vector<double> x = {0.0, 0.1, 0.2, 0.3};
  const std::vector<std::int8_t> l = {1, 0, 1, 0};
  const auto runs = label_runs(x, l, 0.17, 0.23);  // inside the third sample's run [0.15, 0.25]
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].label, 1);
  EXPECT_TRUE(label_runs({}, {}, 0, 1).empty());
  const std::vector<double> one = {2.0};
  const std::vector<std::int8_t> one_label = {0};
  ASSERT_EQ(label_runs(one, one_label, 0, 5).size(), 1u);
}

}  // namespace label_runs_test
}  // namespace lmc::ui
