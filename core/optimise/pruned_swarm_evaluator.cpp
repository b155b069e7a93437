#include "core/optimise/pruned_swarm_evaluator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/metric/cost_lower_bound.h"
#include "core/metric/placement_metric.h"

namespace lmc {

PrunedSwarmEvaluator::PrunedSwarmEvaluator(std::span<const PreparedFrame> frames, int layouts, int devices,
                                           const VisibilityLimits& limits, const SwarmCostSettings& settings)
    : PrunedSwarmEvaluator(frames, layouts, devices,
                           same_limits(limits, static_cast<size_t>(std::clamp(devices, 0, kMaxDevices))), settings) {}

PrunedSwarmEvaluator::PrunedSwarmEvaluator(std::span<const PreparedFrame> frames, int layouts, int devices,
                                           std::span<const VisibilityLimits> slot_limits,
                                           const SwarmCostSettings& settings)
    : frames_(frames),
      layouts_(layouts),
      devices_(devices),
      limits_(slot_limits.begin(), slot_limits.end()),
      settings_(settings),
      robust_(settings.metric == PlacementMetricKind::kRobust),
      prune_(settings.round_frames > 0 && (!robust_ || robust_bound_holds(settings.weights))) {
  if (settings.round_frames < 0) throw Error("round_frames must be ≥ 0 (0 = no pruning)");
  const auto nl = static_cast<size_t>(layouts), nd = static_cast<size_t>(devices);
  const std::vector<FrameRun> chunks = chunk_runs(frames.size());
  const size_t per_round =
      prune_ ? std::max<size_t>(1, static_cast<size_t>(settings.round_frames) / kSwarmChunkFrames) : chunks.size();
  const size_t count = chunks.empty() ? 0 : (chunks.size() + per_round - 1) / per_round;
  rounds_.resize(count);
  for (size_t c = 0; c < chunks.size(); ++c) rounds_[c % count].push_back(chunks[c]);
  partial_counts_.assign(robust_ ? 0 : nl * (nd + 1), 0);
  partial_tallies_.assign(robust_ ? nl : 0, LayoutTally(devices));
}

bool PrunedSwarmEvaluator::evaluate(std::span<const DeviceView> views, std::span<const double> footprint,
                                    std::span<const double> best, std::span<double> cost, tbb::task_arena& arena,
                                    std::stop_token stop) {
  const auto nl = static_cast<size_t>(layouts_), nd = static_cast<size_t>(devices_);
  if (views.size() != nl * nd || best.size() != nl || cost.size() != nl || (robust_ && footprint.size() != nl)) {
    throw Error("PrunedSwarmEvaluator: inconsistent sizes");
  }
  active_.resize(nl);
  for (size_t i = 0; i < nl; ++i) active_[i] = i;
  std::fill(partial_counts_.begin(), partial_counts_.end(), 0);
  for (auto& t : partial_tallies_) t = LayoutTally(devices_);
  const auto total_frames = static_cast<std::int64_t>(frames_.size());
  std::int64_t counted = 0;
  for (size_t r = 0; r < rounds_.size() && !active_.empty(); ++r) {
    const auto na = static_cast<int>(active_.size());
    active_views_.clear();
    for (const size_t i : active_) active_views_.insert(active_views_.end(), &views[i * nd], &views[i * nd] + nd);
    std::int64_t round_frames = 0;
    for (const FrameRun& run : rounds_[r]) round_frames += static_cast<std::int64_t>(run.count);
    bool ok = false;
    if (!robust_) {
      round_counts_.assign(active_.size() * (nd + 1), 0);
      arena.execute([&] {
        ok = worst_finger_histograms(active_views_, na, devices_, frames_, rounds_[r], limits_, round_counts_, stop);
      });
      if (!ok) return false;
      for (size_t a = 0; a < active_.size(); ++a) {
        for (size_t k = 0; k <= nd; ++k) partial_counts_[active_[a] * (nd + 1) + k] += round_counts_[a * (nd + 1) + k];
      }
    } else {
      round_tallies_.assign(active_.size(), LayoutTally(devices_));
      arena.execute([&] {
        ok = layout_tallies(active_views_, na, devices_, frames_, rounds_[r], limits_, round_tallies_, stop);
      });
      if (!ok) return false;
      for (size_t a = 0; a < active_.size(); ++a) partial_tallies_[active_[a]].add(round_tallies_[a]);
    }
    counted += round_frames;
    device_frame_evaluations_ += static_cast<std::int64_t>(active_.size() * nd) * round_frames;
    if (r + 1 == rounds_.size()) break;
    const std::int64_t remaining = total_frames - counted;
    std::erase_if(active_, [&](size_t i) {
      if (!std::isfinite(best[i])) return false;
      const double bound =
          robust_ ? robust_cost_lower_bound(partial_tallies_[i], remaining, footprint[i], settings_.weights)
                  : study_cost_lower_bound(std::span<const std::int64_t>(partial_counts_).subspan(i * (nd + 1), nd + 1),
                                           remaining);
      if (!(bound >= best[i])) return false;
      cost[i] = std::numeric_limits<double>::infinity();  // stands for "not below its best": never compared further
      ++layouts_stopped_early_;
      return true;
    });
  }
  for (const size_t i : active_) {
    cost[i] = robust_ ? robust_terms(partial_tallies_[i], footprint[i], settings_.weights).total
                      : placement_metric(std::span<const std::int64_t>(partial_counts_).subspan(i * (nd + 1), nd + 1));
  }
  return true;
}

}  // namespace lmc
