#include "core/metric/cost_lower_bound.h"

#include <gtest/gtest.h>

#include <limits>
#include <numeric>
#include <vector>

#include "core/io/layout_json.h"
#include "core/layout/layout.h"
#include "core/metric/placement_metric.h"
#include "core/visibility/device_view.h"
#include "core/visibility/visibility_params.h"
#include "tests/support/mc_frames.h"

namespace lmc {
namespace cost_lower_bound_test {  // named: the unity build puts several tests in one file

const std::vector<PreparedFrame>& bound_frames() {
  return test::mc_frames(300, 11);
}

std::vector<DeviceView> views_of(const Layout& l) {
  std::vector<DeviceView> v;
  for (const auto& d : l.devices) v.push_back(DeviceView::from_device(d));
  return v;
}

// The first `counted` frames as the part counted so far, the whole set as the final count.
struct Split {
  LayoutTally partial, full;
  std::int64_t remaining = 0;
};
Split split_tally(const Layout& layout, int counted) {
  const auto views = views_of(layout);
  const VisibilityLimits lim = make_limits(VisibilityParams::from_sensor(common_sensor(layout)));
  std::vector<int> first(static_cast<size_t>(counted));
  std::iota(first.begin(), first.end(), 0);
  Split s;
  s.full = tally_layout(views, bound_frames(), lim);
  s.partial =
      counted > 0 ? tally_layout(views, bound_frames(), lim, kAxisCutMm, first) : LayoutTally(layout.device_count());
  s.remaining = static_cast<std::int64_t>(bound_frames().size()) - counted;
  return s;
}

std::vector<Layout> layouts_to_bound() {
  std::vector<Layout> out;
  for (const char* name : {"paper-initial", "paper-optimized", "paper-optimized-as-processed"}) {
    out.push_back(load_layout_or_preset(name));
  }
  return out;
}

TEST(CostLowerBound, NeverAboveTheFinalCostAndEqualToItWhenEveryFrameIsCounted) {
  RobustWeights heavy;
  heavy.axis_cut = 25;
  heavy.participation = 20;
  heavy.inside_cut = 3;
  RobustWeights zero = RobustWeights::all_off();
  int strictly_below = 0;
  for (const Layout& layout : layouts_to_bound()) {
    const double footprint = footprint_overlap_share(layout);
    for (const int counted : {0, 1, 64, 150, 299, 300}) {
      const Split s = split_tally(layout, counted);
      const double study = placement_metric(s.full.c);
      const double study_bound = study_cost_lower_bound(s.partial.c, s.remaining);
      EXPECT_LE(study_bound, study) << layout.name << " after " << counted;
      for (const RobustWeights& w : {RobustWeights{}, heavy, zero}) {
        const double cost = robust_terms(s.full, footprint, w).total;
        const double bound = robust_cost_lower_bound(s.partial, s.remaining, footprint, w);
        EXPECT_LE(bound, cost) << layout.name << " after " << counted;
        if (counted == 300) {
          EXPECT_EQ(bound, cost);
        }
        if (bound < cost) ++strictly_below;
      }
      if (counted == 300) {
        EXPECT_EQ(study_bound, study);
      }
    }
  }
  EXPECT_GT(strictly_below, 0);  // the bound is a bound, not the cost itself
}

TEST(CostLowerBound, TheBestCaseCountsEveryRemainingFrameAsPerfect) {
  const Split s = split_tally(load_layout_or_preset("paper-initial"), 100);
  const LayoutTally t = best_case_tally(s.partial, s.remaining);
  EXPECT_EQ(t.frames, 300);
  EXPECT_EQ(t.c.back(), s.partial.c.back() + 200);
  for (size_t d = 0; d < t.device_seeing_frames.size(); ++d) {
    EXPECT_EQ(t.device_seeing_frames[d], s.partial.device_seeing_frames[d] + 200);
    EXPECT_EQ(t.device_cut_frames[d], s.partial.device_cut_frames[d]);
    EXPECT_EQ(t.device_off_centre[d], s.partial.device_off_centre[d]);
  }
  const std::vector<std::int64_t> c = best_case_histogram(s.partial.c, 200);
  EXPECT_EQ(c, t.c);
}

TEST(CostLowerBound, HoldsOnlyForFiniteNonNegativeWeights) {
  EXPECT_TRUE(robust_bound_holds(RobustWeights{}));
  RobustWeights w;
  w.centring = -0.01;
  EXPECT_FALSE(robust_bound_holds(w));
  w = RobustWeights{};
  w.axis_cut = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(robust_bound_holds(w));
  w = RobustWeights{};
  w.redundancy = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(robust_bound_holds(w));
}

}  // namespace cost_lower_bound_test
}  // namespace lmc
