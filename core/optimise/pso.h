#pragma once
// Global-best particle swarm search for a layout (docs/algorithms/search.md). A synchronous
// function: it owns no threads (oneTBB parallelises the evaluation inside), reports progress
// through a callback on the calling thread after every iteration, checks the stop token between
// chunks of work, and returns Completed or Cancelled with the best layout found so far.
//
// Pruning: a particle is counted on the pose set in rounds and dropped as soon as a lower bound
// on its cost reaches its own best (pruned_swarm_evaluator.h); that changes no comparison, so the
// search is the same with or without it (PsoSettings::prune_round_frames).
//
// Determinism: every random number is drawn on the calling thread from one std::mt19937_64 seeded
// with `seed`, in a fixed order; the cost of a particle is computed from integer counts, so the
// result is identical for any number of threads.
//
// Update (per particle i, dimension k, r1, r2 uniform in [0, 1)):
//   v ← w·v + c1·r1·(pbest − x) + c2·r2·(gbest − x);  x ← x + v.
// Boundary handling: a coordinate that leaves its bounds is clamped onto the bound and its
// velocity component is set to zero (so the particle can slide along the wall but not stick
// outside). Initial positions are uniform in the bounds; initial velocities uniform in
// ±0.1·(max − min). With `start_from_layout`, particle 0 starts exactly at the start layout
// (clamped into the bounds) so the result is never worse than the start. Locked parameters never
// move and always hold the start layout's values.
#include <cstdint>
#include <functional>
#include <span>
#include <stop_token>
#include <vector>

#include "core/layout/layout.h"
#include "core/metric/coverage.h"
#include "core/metric/robust_metric.h"
#include "core/optimise/search_space.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

struct PsoSettings {
  int particles = 30;
  int iterations = 100;
  double w = 0.9;   // inertia
  double c1 = 0.5;  // cognitive (own best)
  double c2 = 0.3;  // social (swarm best)
  std::uint64_t seed = 1;
  int threads = 0;  // 0 = all hardware threads; the result does not depend on it
  bool start_from_layout = false;
  double phalanx_radius_mm = 10.0;
  // The cost the swarm minimises: the study's M (the reference, bit for bit what run_pso always
  // did) or the robust metric R of robust_metric.h with these weights.
  PlacementMetricKind metric = PlacementMetricKind::kStudy;
  RobustWeights weights;  // each slot's axis cut is its sensor model's (SensorModel::axis_cut_mm)
  // Frames counted between two checks of the pruning bound (cost_lower_bound.h; rounded down to
  // whole chunks of 64). 0 counts every particle on every frame. The result is the same either
  // way; only the time differs.
  int prune_round_frames = 1024;
};

enum class JobStatus : int { kCompleted = 0, kCancelled = 1 };

struct PsoProgress {
  int iteration = 0;   // iterations finished (0 = the initial swarm has been evaluated)
  int iterations = 0;  // planned
  double best_cost = 0;
  std::int64_t layout_evaluations = 0;        // particles evaluated so far
  std::int64_t device_frame_evaluations = 0;  // (device, frame) visibility tests so far
  Layout best_layout;                         // the best layout so far (the workbench draws it as ghost controllers)
};
using PsoProgressCallback = std::function<void(const PsoProgress&)>;

struct PsoResult {
  JobStatus status = JobStatus::kCompleted;
  Layout best_layout;
  double best_cost = 0;  // M or R, as `metric` says
  PlacementMetricKind metric = PlacementMetricKind::kStudy;
  Coverage best_coverage;                 // of best_layout on the pose set
  RobustTerms best_terms;                 // every term of the robust metric for best_layout (also after a study search)
  std::vector<double> best_cost_history;  // best cost after the initial swarm and each iteration
  int iterations_done = 0;
  std::int64_t layout_evaluations = 0;
  std::int64_t device_frame_evaluations = 0;  // (device, frame) visibility tests actually run
  std::int64_t layouts_stopped_early = 0;     // layout evaluations stopped early by the bound
  double seconds = 0;
};

// Searches placements for the devices of `start` (1–8 devices; their slots, serials, offsets and
// sensor models are kept) on `frames`. Each slot sees through its own device's sensor model in
// `start` (range, field of view, axis cut) wherever the search moves it: a mixed rig stays mixed.
// Throws lmc::Error for an invalid search space, start layout or settings.
PsoResult run_pso(const Layout& start, const SearchSpace& space, std::span<const PreparedFrame> frames,
                  const PsoSettings& settings, const PsoProgressCallback& progress = {}, std::stop_token stop = {});

// The cost (M) of one layout on prepared frames; the building block of run_pso, exposed for tests
// and benchmarks. Uses oneTBB over frames.
double layout_cost(const Layout& layout, std::span<const PreparedFrame> frames, double phalanx_radius_mm = 10.0);

// Every robust term of one layout (what `lmc evaluate` prints and the search minimises with
// PlacementMetricKind::kRobust). With `frame_subset`, only those frames.
RobustTerms layout_robust_terms(const Layout& layout, std::span<const PreparedFrame> frames,
                                const RobustWeights& weights = {}, double phalanx_radius_mm = 10.0,
                                std::span<const int> frame_subset = {});

}  // namespace lmc
