#pragma once
// The swarm's cost evaluation with pruning (pso.cpp's inner loop). A particle only matters to the
// swarm if its cost falls below its own best, so the pose set is counted in rounds and, after each
// round, a layout whose best-case cost (cost_lower_bound.h) already reaches its best is dropped:
// its cost cannot be below its best (improvement is strict), nor below the swarm's best (never
// above its own). Every comparison the swarm makes comes out as without the rounds, so the search
// is the same bit for bit; only the visibility tests skipped differ.
//
// Rounds take every R-th chunk of frames, so that each spans the whole pose set (all reference
// poses) and a poor layout shows early. Counts are integers: the order of frames changes nothing
// else, and the result does not depend on the thread count.
#include <cstdint>
#include <span>
#include <stop_token>
#include <vector>

#include <tbb/task_arena.h>

#include "core/metric/layout_tally.h"
#include "core/metric/robust_metric.h"
#include "core/optimise/swarm_evaluator.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

struct SwarmCostSettings {
  PlacementMetricKind metric = PlacementMetricKind::kStudy;
  RobustWeights weights;    // robust metric only; pruning needs them finite and ≥ 0; cuts are per slot
  int round_frames = 1024;  // frames between two checks of the bound (whole chunks); 0: no pruning
};

class PrunedSwarmEvaluator {
 public:
  PrunedSwarmEvaluator(std::span<const PreparedFrame> frames, int layouts, int devices, const VisibilityLimits& limits,
                       const SwarmCostSettings& settings);
  // A mixed rig: slot d of every layout through slot_limits[d] (`devices` entries).
  PrunedSwarmEvaluator(std::span<const PreparedFrame> frames, int layouts, int devices,
                       std::span<const VisibilityLimits> slot_limits, const SwarmCostSettings& settings);

  // `views`: layouts × devices, layout-major; `footprint`: each layout's footprint-overlap share
  // (robust metric); `best`: each layout's best cost so far (+inf: none yet). Writes each layout's
  // cost, or +inf for a layout dropped early (its cost is not below its best). Runs in `arena`.
  // Returns false when `stop` was requested before the end.
  bool evaluate(std::span<const DeviceView> views, std::span<const double> footprint, std::span<const double> best,
                std::span<double> cost, tbb::task_arena& arena, std::stop_token stop);

  std::int64_t device_frame_evaluations() const { return device_frame_evaluations_; }  // tests actually run
  std::int64_t layouts_stopped_early() const { return layouts_stopped_early_; }

 private:
  std::span<const PreparedFrame> frames_;
  int layouts_, devices_;
  std::vector<VisibilityLimits> limits_;  // per slot
  SwarmCostSettings settings_;
  bool robust_, prune_;
  std::vector<std::vector<FrameRun>> rounds_;
  std::vector<std::int64_t> partial_counts_;  // study: layouts × (devices + 1)
  std::vector<LayoutTally> partial_tallies_;  // robust: one per layout
  std::vector<size_t> active_;
  std::vector<DeviceView> active_views_;
  std::vector<std::int64_t> round_counts_;
  std::vector<LayoutTally> round_tallies_;
  std::int64_t device_frame_evaluations_ = 0;
  std::int64_t layouts_stopped_early_ = 0;
};

}  // namespace lmc
