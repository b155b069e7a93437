#include "core/metric/cost_lower_bound.h"

#include <cmath>

#include "core/metric/placement_metric.h"

namespace lmc {

std::vector<std::int64_t> best_case_histogram(std::span<const std::int64_t> partial_c, std::int64_t remaining) {
  std::vector<std::int64_t> c(partial_c.begin(), partial_c.end());
  if (!c.empty()) c.back() += remaining;
  return c;
}

LayoutTally best_case_tally(const LayoutTally& partial, std::int64_t remaining) {
  LayoutTally t = partial;
  t.frames += remaining;
  if (!t.c.empty()) t.c.back() += remaining;
  if (!t.c_inside_cut.empty()) t.c_inside_cut.back() += remaining;
  for (auto& seeing : t.device_seeing_frames) seeing += remaining;
  return t;
}

double study_cost_lower_bound(std::span<const std::int64_t> partial_c, std::int64_t remaining) {
  return placement_metric(best_case_histogram(partial_c, remaining));
}

double robust_cost_lower_bound(const LayoutTally& partial, std::int64_t remaining, double footprint_share,
                               const RobustWeights& weights) {
  return robust_terms(best_case_tally(partial, remaining), footprint_share, weights).total;
}

bool robust_bound_holds(const RobustWeights& w) {
  for (const double x : {w.redundancy, w.participation, w.axis_cut, w.centring, w.footprint, w.inside_cut}) {
    if (!(std::isfinite(x) && x >= 0.0)) return false;
  }
  return std::isfinite(w.participation_floor);
}

}  // namespace lmc
