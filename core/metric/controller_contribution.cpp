#include "core/metric/controller_contribution.h"

#include "core/metric/coverage.h"
#include "core/metric/placement_metric.h"

namespace lmc {
namespace {

double contribution_share(std::int64_t part, std::int64_t whole) {
  return whole > 0 ? static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

// M and the ≥ 2 share of `table` without device d.
struct Without {
  double metric = 0;
  double redundant = 0;
};
Without coverage_without(const VisibilityTable& table, int d, std::span<const int> subset, std::int64_t frames) {
  // Without its only controller nothing is seen: every frame has an unseen finger.
  if (table.devices <= 1) return {frames > 0 ? 1.0 : 0.0, 0.0};
  std::vector<std::span<const FingerBits>> cols;
  for (int e = 0; e < table.devices; ++e) {
    if (e != d) cols.push_back(table.device_column(e));
  }
  const Coverage without = compute_coverage(std::span<const std::span<const FingerBits>>(cols), subset);
  return {without.metric, redundant_share(without.c)};
}

// Frames (of `subset`, or all) in which device d sees some finger.
std::int64_t seeing_frames(const VisibilityTable& table, int d, std::span<const int> subset) {
  const std::span<const FingerBits> col = table.device_column(d);
  std::int64_t n = 0;
  if (subset.empty()) {
    for (const FingerBits b : col) n += b != 0;
  } else {
    for (const int j : subset) n += col[static_cast<size_t>(j)] != 0;
  }
  return n;
}

}  // namespace

double redundant_share(std::span<const std::int64_t> c) {
  std::int64_t all = 0, redundant = 0;
  for (size_t i = 0; i < c.size(); ++i) {
    all += c[i];
    if (i >= 2) redundant += c[i];
  }
  return contribution_share(redundant, all);
}

std::vector<ControllerContribution> controller_contributions(const VisibilityTable& table, const LayoutTally& tally,
                                                             const std::vector<std::string>& slots,
                                                             std::span<const int> subset,
                                                             const VisibilityTable* inside_cut) {
  std::vector<ControllerContribution> out;
  const Coverage all = compute_coverage(table, subset);
  const double m_all = all.metric;
  const double s2_all = redundant_share(all.c);
  Coverage inside_all;
  double s2_inside_all = 0;
  if (inside_cut != nullptr) {
    inside_all = compute_coverage(*inside_cut, subset);
    s2_inside_all = redundant_share(inside_all.c);
  }
  for (int d = 0; d < table.devices; ++d) {
    const auto dd = static_cast<size_t>(d);
    ControllerContribution c;
    c.slot = dd < slots.size() ? slots[dd] : "device " + std::to_string(d + 1);
    c.seeing_share = contribution_share(tally.device_seeing_frames[dd], tally.frames);
    c.sole_share = contribution_share(tally.device_sole_frames[dd], tally.frames);
    c.cut_share = contribution_share(tally.device_cut_frames[dd], tally.device_seeing_frames[dd]);
    c.off_centre = tally.device_seeing_frames[dd] > 0
                       ? static_cast<double>(tally.device_off_centre[dd]) / kOffCentreScale /
                             static_cast<double>(tally.device_seeing_frames[dd])
                       : 1.0;
    const Without without = coverage_without(table, d, subset, tally.frames);
    c.metric_without = without.metric;
    c.redundant_without = without.redundant;
    c.counts = c.metric_without > m_all || c.redundant_without < s2_all;
    if (inside_cut != nullptr) {
      c.seeing_inside_cut_share = contribution_share(seeing_frames(*inside_cut, d, subset), tally.frames);
      const Without inside_without = coverage_without(*inside_cut, d, subset, tally.frames);
      c.metric_inside_cut_without = inside_without.metric;
      c.redundant_inside_cut_without = inside_without.redundant;
      c.counts_inside_cut = inside_without.metric > inside_all.metric || inside_without.redundant < s2_inside_all;
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace lmc
