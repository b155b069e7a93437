#include "core/optimise/pso.h"

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "core/common/error.h"
#include "core/metric/placement_metric.h"
#include "core/optimise/pruned_swarm_evaluator.h"
#include "core/optimise/swarm_evaluator.h"
#include "core/visibility/device_view.h"

namespace lmc {
namespace {

double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

void check_pso_inputs(const Layout& start, const SearchSpace& space, std::span<const PreparedFrame> frames,
                      const PsoSettings& s) {
  if (const std::string problem = validate_layout(start); !problem.empty()) throw Error("start layout " + problem);
  if (const std::string problem = space.validate(); !problem.empty()) throw Error(problem);
  if (s.particles < 1 || s.particles > 100000) throw Error("particles must be 1…100000");
  if (s.iterations < 0 || s.iterations > 1000000) throw Error("iterations must be 0…1000000");
  if (!std::isfinite(s.w) || !std::isfinite(s.c1) || !std::isfinite(s.c2)) throw Error("w, c1, c2 must be finite");
  if (s.threads < 0) throw Error("threads must be ≥ 0 (0 = all)");
  if (s.prune_round_frames < 0) throw Error("prune_round_frames must be ≥ 0 (0 = no pruning)");
  if (frames.empty()) throw Error("the pose set is empty");
}

// The swarm: positions, velocities and personal bests, particle-major ([particle * dim + k]), and
// each searched dimension's bounds.
struct Swarm {
  size_t dim = 0;
  std::vector<double> x, v, pbest, gbest, pbest_cost, lo, hi;
  double gbest_cost = std::numeric_limits<double>::infinity();
};

Swarm initial_swarm(const Layout& start, const SearchSpace& space, const std::vector<std::pair<int, int>>& dims,
                    const PsoSettings& s, std::mt19937_64& rng) {
  const auto np = static_cast<size_t>(s.particles);
  const size_t dim = dims.size();
  Swarm sw;
  sw.dim = dim;
  sw.x.resize(np * dim);
  sw.v.resize(np * dim);
  sw.pbest.resize(np * dim);
  sw.gbest.resize(dim);
  sw.pbest_cost.assign(np, std::numeric_limits<double>::infinity());
  sw.lo.resize(dim);
  sw.hi.resize(dim);
  std::vector<double> start_x(dim);
  for (size_t k = 0; k < dim; ++k) {
    const auto [d, p] = dims[k];
    const ParamBounds& b = space.bounds[static_cast<size_t>(p)];
    sw.lo[k] = b.min;
    sw.hi[k] = b.max;
    start_x[k] = std::clamp(start.devices[static_cast<size_t>(d)].pose.get(p), b.min, b.max);
  }
  // Initial swarm, drawn particle by particle, dimension by dimension, on this thread.
  for (size_t i = 0; i < np; ++i) {
    for (size_t k = 0; k < dim; ++k) {
      const double span = sw.hi[k] - sw.lo[k];
      const double pos = sw.lo[k] + uniform01(rng) * span;
      const double vel = (2.0 * uniform01(rng) - 1.0) * 0.1 * span;
      sw.x[i * dim + k] = (i == 0 && s.start_from_layout) ? start_x[k] : pos;
      sw.v[i * dim + k] = vel;
    }
  }
  return sw;
}

// One iteration's move, particle by particle, dimension by dimension (the draws in that order).
void move_swarm(Swarm& sw, const PsoSettings& s, std::mt19937_64& rng) {
  const size_t dim = sw.dim;
  const auto np = static_cast<size_t>(s.particles);
  std::vector<double>&x = sw.x, &v = sw.v;
  for (size_t i = 0; i < np; ++i) {
    for (size_t k = 0; k < dim; ++k) {
      const size_t ik = i * dim + k;
      const double r1 = uniform01(rng);
      const double r2 = uniform01(rng);
      v[ik] = s.w * v[ik] + s.c1 * r1 * (sw.pbest[ik] - x[ik]) + s.c2 * r2 * (sw.gbest[k] - x[ik]);
      x[ik] += v[ik];
      // Boundary: clamp onto the wall and stop moving across it.
      if (x[ik] < sw.lo[k]) {
        x[ik] = sw.lo[k];
        v[ik] = 0.0;
      } else if (x[ik] > sw.hi[k]) {
        x[ik] = sw.hi[k];
        v[ik] = 0.0;
      }
    }
  }
}

// The best layout's coverage and robust terms, for the summary.
void score_best_layout(PsoResult& result, std::span<const PreparedFrame> frames, const PsoSettings& s,
                       tbb::task_arena& arena) {
  VisibilityTable table;
  arena.execute([&] { table = compute_visibility(result.best_layout, frames, s.phalanx_radius_mm); });
  result.best_coverage = compute_coverage(table);
  arena.execute(
      [&] { result.best_terms = layout_robust_terms(result.best_layout, frames, s.weights, s.phalanx_radius_mm); });
}

// The layout particle `xi` stands for: the start layout with each searched dimension set.
Layout swarm_layout(const Layout& start, const std::vector<std::pair<int, int>>& dims, const double* xi) {
  Layout l = start;
  for (size_t k = 0; k < dims.size(); ++k) {
    const auto [d, p] = dims[k];
    l.devices[static_cast<size_t>(d)].pose.set(p, xi[k]);
  }
  return l;
}

// Personal and global bests after an evaluation: strict improvement; ties keep the earlier
// (lower index) one.
void update_swarm_bests(Swarm& sw, const std::vector<double>& cost) {
  const size_t dim = sw.dim;
  for (size_t i = 0; i < cost.size(); ++i) {
    if (cost[i] < sw.pbest_cost[i]) {
      sw.pbest_cost[i] = cost[i];
      std::copy_n(&sw.x[i * dim], dim, &sw.pbest[i * dim]);
    }
    if (cost[i] < sw.gbest_cost) {
      sw.gbest_cost = cost[i];
      std::copy_n(&sw.x[i * dim], dim, sw.gbest.begin());
    }
  }
}

// The result's best layout and cost; cancelled before the first evaluation finished, the best
// known layout is the start.
void set_best_layout(PsoResult& result, const Swarm& sw, const Layout& start,
                     const std::vector<std::pair<int, int>>& dims) {
  if (std::isfinite(sw.gbest_cost)) {
    result.best_layout = swarm_layout(start, dims, sw.gbest.data());
    result.best_cost = sw.gbest_cost;
  } else {
    result.best_layout = start;
    result.best_cost = std::numeric_limits<double>::infinity();
  }
}

}  // namespace

PsoResult run_pso(const Layout& start, const SearchSpace& space, std::span<const PreparedFrame> frames,
                  const PsoSettings& s, const PsoProgressCallback& progress, std::stop_token stop) {
  const auto t0 = std::chrono::steady_clock::now();
  check_pso_inputs(start, space, frames, s);

  const int devices = start.device_count();
  const auto nd = static_cast<size_t>(devices);
  const auto np = static_cast<size_t>(s.particles);
  const auto dims = space.dimensions(devices);
  const size_t dim = dims.size();
  // Slot d keeps the start layout's sensor model d wherever the search moves it.
  const std::vector<VisibilityLimits> limits = device_limits(start, s.phalanx_radius_mm);

  std::mt19937_64 rng(s.seed);
  Swarm sw = initial_swarm(start, space, dims, s, rng);

  std::unique_ptr<tbb::task_arena> arena;
  arena = std::make_unique<tbb::task_arena>(s.threads > 0 ? s.threads : tbb::this_task_arena::max_concurrency());

  std::vector<DeviceView> views(np * nd);
  std::vector<double> cost(np);
  std::vector<double> footprint(np, 0.0);
  PsoResult result;
  result.status = JobStatus::kCompleted;
  result.metric = s.metric;
  const bool robust = s.metric == PlacementMetricKind::kRobust;
  PrunedSwarmEvaluator evaluator(frames, s.particles, devices, limits,
                                 SwarmCostSettings{s.metric, s.weights, s.prune_round_frames});

  // Evaluates the whole swarm; false when cancelled.
  auto evaluate = [&]() {
    for (size_t i = 0; i < np; ++i) {
      const Layout l = swarm_layout(start, dims, &sw.x[i * dim]);
      for (size_t d = 0; d < nd; ++d) views[i * nd + d] = DeviceView::from_device(l.devices[d]);
      if (robust) footprint[i] = footprint_overlap_share(l);
    }
    const bool ok = evaluator.evaluate(views, footprint, sw.pbest_cost, cost, *arena, stop);
    result.device_frame_evaluations = evaluator.device_frame_evaluations();
    result.layouts_stopped_early = evaluator.layouts_stopped_early();
    if (!ok) return false;
    result.layout_evaluations += s.particles;
    update_swarm_bests(sw, cost);
    return true;
  };

  auto report = [&](int iteration) {
    result.best_cost_history.push_back(sw.gbest_cost);
    if (progress) {
      PsoProgress p{iteration, s.iterations, sw.gbest_cost, result.layout_evaluations, result.device_frame_evaluations,
                    {}};
      if (std::isfinite(sw.gbest_cost)) p.best_layout = swarm_layout(start, dims, sw.gbest.data());
      progress(p);
    }
  };

  bool cancelled = stop.stop_requested() || !evaluate();
  if (!cancelled) report(0);
  for (int it = 1; it <= s.iterations && !cancelled; ++it) {
    if (stop.stop_requested()) {
      cancelled = true;
      break;
    }
    move_swarm(sw, s, rng);
    if (!evaluate()) {
      cancelled = true;
      break;
    }
    result.iterations_done = it;
    report(it);
  }

  result.status = cancelled ? JobStatus::kCancelled : JobStatus::kCompleted;
  set_best_layout(result, sw, start, dims);
  if (!cancelled) score_best_layout(result, frames, s, *arena);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

double layout_cost(const Layout& layout, std::span<const PreparedFrame> frames, double phalanx_radius_mm) {
  const int devices = layout.device_count();
  if (devices < 1 || devices > kMaxDevices) throw Error("a layout needs 1 to 8 devices");
  std::vector<DeviceView> views;
  for (const auto& d : layout.devices) views.push_back(DeviceView::from_device(d));
  std::vector<std::int64_t> counts(static_cast<size_t>(devices) + 1);
  worst_finger_histograms(views, 1, devices, frames, chunk_runs(frames.size()),
                          device_limits(layout, phalanx_radius_mm), counts);
  return placement_metric(counts);
}

RobustTerms layout_robust_terms(const Layout& layout, std::span<const PreparedFrame> frames,
                                const RobustWeights& weights, double phalanx_radius_mm,
                                std::span<const int> frame_subset) {
  std::vector<DeviceView> views;
  for (const auto& d : layout.devices) views.push_back(DeviceView::from_device(d));
  const LayoutTally t = tally_layout(views, frames, device_limits(layout, phalanx_radius_mm), frame_subset);
  return robust_terms(t, footprint_overlap_share(layout), weights);
}

}  // namespace lmc
