#include "core/optimise/multi_start.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "core/common/error.h"

namespace lmc {
namespace {

bool multi_start_devices_close(const LayoutDevice& a, const LayoutDevice& b, double mm, double deg) {
  return std::abs(a.pose.x_mm - b.pose.x_mm) <= mm && std::abs(a.pose.z_mm - b.pose.z_mm) <= mm &&
         std::abs(a.pose.rx_deg - b.pose.rx_deg) <= deg && std::abs(a.pose.ry_deg - b.pose.ry_deg) <= deg;
}

}  // namespace

bool same_arrangement(const Layout& a, const Layout& b, double mm, double deg) {
  if (a.devices.size() != b.devices.size()) return false;
  std::vector<size_t> order(b.devices.size());
  std::iota(order.begin(), order.end(), 0);
  do {
    bool all = true;
    for (size_t i = 0; i < order.size() && all; ++i) {
      all = multi_start_devices_close(a.devices[i], b.devices[order[i]], mm, deg);
    }
    if (all) return true;
  } while (std::next_permutation(order.begin(), order.end()));
  return false;
}

MultiStartResult run_multi_start(const Layout& start, const SearchSpace& space, std::span<const PreparedFrame> frames,
                                 const PsoSettings& settings, int starts, const MultiStartProgressCallback& progress,
                                 std::stop_token stop) {
  if (starts < 1 || starts > 64) throw Error("starts must be 1…64");
  const auto t0 = std::chrono::steady_clock::now();
  MultiStartResult out;
  for (int k = 0; k < starts; ++k) {
    PsoSettings s = settings;
    s.seed = settings.seed + static_cast<std::uint64_t>(k);
    s.start_from_layout = settings.start_from_layout && k == 0;
    PsoProgressCallback forward;
    if (progress) forward = [&](const PsoProgress& p) { progress({k, starts, p}); };
    PsoResult r = run_pso(start, space, frames, s, forward, stop);
    if (r.status == JobStatus::kCancelled) {
      out.status = JobStatus::kCancelled;
      break;
    }
    out.runs.push_back(std::move(r));
    out.seeds.push_back(s.seed);
  }
  std::vector<int> by_cost(out.runs.size());
  std::iota(by_cost.begin(), by_cost.end(), 0);
  std::stable_sort(by_cost.begin(), by_cost.end(), [&](int a, int b) {
    return out.runs[static_cast<size_t>(a)].best_cost < out.runs[static_cast<size_t>(b)].best_cost;
  });
  if (!by_cost.empty()) out.best = by_cost.front();
  for (size_t i = 1; i < by_cost.size(); ++i) {
    const Layout& candidate = out.runs[static_cast<size_t>(by_cost[i])].best_layout;
    bool distinct = !same_arrangement(candidate, out.runs[static_cast<size_t>(out.best)].best_layout);
    for (const int kept : out.runners_up) {
      distinct = distinct && !same_arrangement(candidate, out.runs[static_cast<size_t>(kept)].best_layout);
    }
    if (distinct) out.runners_up.push_back(by_cost[i]);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace lmc
