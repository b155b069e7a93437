#include "core/optimise/multi_start.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/hand/pose_set_generator.h"
#include "tests/support/mc_frames.h"

namespace lmc {
namespace multi_start_test {

const std::vector<PreparedFrame>& ms_frames() {
  return test::mc_frames(120, 3);
}

PsoSettings ms_small(PlacementMetricKind metric, int threads = 0) {
  PsoSettings s;
  s.particles = 8;
  s.iterations = 6;
  s.seed = 17;
  s.threads = threads;
  s.metric = metric;
  return s;
}

TEST(RobustSearch, WithEveryWeightZeroTheRobustSearchIsTheStudySearch) {
  PsoSettings study = ms_small(PlacementMetricKind::kStudy);
  PsoSettings robust = ms_small(PlacementMetricKind::kRobust);
  robust.weights = RobustWeights::all_off();
  const SearchSpace space = table_search_space();
  const PsoResult a = run_pso(default_start_layout(3), space, ms_frames(), study);
  const PsoResult b = run_pso(default_start_layout(3), space, ms_frames(), robust);
  EXPECT_EQ(a.best_cost_history, b.best_cost_history);
  EXPECT_EQ(a.best_layout, b.best_layout);
}

TEST(RobustSearch, SameSeedSameLayoutOnOneOrTwoThreads) {
  const SearchSpace space = table_search_space();
  const PsoResult a = run_pso(default_start_layout(4), space, ms_frames(), ms_small(PlacementMetricKind::kRobust, 1));
  const PsoResult b = run_pso(default_start_layout(4), space, ms_frames(), ms_small(PlacementMetricKind::kRobust, 2));
  EXPECT_EQ(a.best_cost_history, b.best_cost_history);
  EXPECT_EQ(a.best_layout, b.best_layout);
  EXPECT_EQ(a.best_terms.total, a.best_cost);
  for (size_t i = 1; i < a.best_cost_history.size(); ++i) EXPECT_LE(a.best_cost_history[i], a.best_cost_history[i - 1]);
}

TEST(RobustSearch, TableBoundsKeepEveryControllerOnTheTable) {
  const PsoResult r =
      run_pso(default_start_layout(4), table_search_space(), ms_frames(), ms_small(PlacementMetricKind::kRobust));
  for (const auto& d : r.best_layout.devices) {
    EXPECT_LE(std::abs(d.pose.x_mm), kTableHalfExtentMm - 40.0);
    EXPECT_LE(std::abs(d.pose.z_mm), kTableHalfExtentMm - 40.0);
  }
}

TEST(MultiStart, EachStartHasItsOwnSeedAndTheBestIsTheLowestCost) {
  const MultiStartResult m = run_multi_start(default_start_layout(3), table_search_space(), ms_frames(),
                                             ms_small(PlacementMetricKind::kRobust), 3);
  ASSERT_EQ(m.runs.size(), 3u);
  EXPECT_EQ(m.seeds, (std::vector<std::uint64_t>{17, 18, 19}));
  ASSERT_GE(m.best, 0);
  for (const auto& r : m.runs) EXPECT_GE(r.best_cost, m.runs[static_cast<size_t>(m.best)].best_cost);
  for (const int k : m.runners_up) {
    EXPECT_NE(k, m.best);
    EXPECT_FALSE(
        same_arrangement(m.runs[static_cast<size_t>(k)].best_layout, m.runs[static_cast<size_t>(m.best)].best_layout));
  }
  // The first start is a plain run_pso with the same seed.
  const PsoResult single =
      run_pso(default_start_layout(3), table_search_space(), ms_frames(), ms_small(PlacementMetricKind::kRobust));
  EXPECT_EQ(single.best_layout, m.runs[0].best_layout);
}

TEST(MultiStart, SwappedControllersAreTheSameArrangementAndAMovedOneIsNot) {
  Layout a = default_start_layout(3);
  Layout b = a;
  std::swap(b.devices[0].pose, b.devices[2].pose);
  EXPECT_TRUE(same_arrangement(a, b));
  b.devices[1].pose.z_mm += 100;
  EXPECT_FALSE(same_arrangement(a, b));
  b = a;
  b.devices[1].pose.ry_deg += 10;  // within 15°
  EXPECT_TRUE(same_arrangement(a, b));
  EXPECT_THROW(run_multi_start(a, table_search_space(), ms_frames(), ms_small(PlacementMetricKind::kRobust), 0), Error);
}

}  // namespace multi_start_test
}  // namespace lmc
