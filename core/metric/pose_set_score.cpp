#include "core/metric/pose_set_score.h"

#include "core/metric/controller_contribution.h"
#include "core/metric/coverage.h"

namespace lmc {

PoseSetScore pose_set_score(const VisibilityTable& table, std::string label, std::string description) {
  PoseSetScore s;
  s.label = std::move(label);
  s.description = std::move(description);
  s.frames = table.frames;
  const Coverage c = compute_coverage(table);
  s.metric = c.metric;
  s.redundant_share = redundant_share(c.c);
  for (int k = 0; k < kNumDigits; ++k) s.finger_seen[static_cast<size_t>(k)] = 1.0 - c.finger_unseen_fraction(k);
  for (int d = 0; d < table.devices; ++d) {
    std::int64_t seeing = 0;
    for (const FingerBits b : table.device_column(d)) seeing += b != 0;
    s.controller_seeing.push_back(table.frames > 0 ? static_cast<double>(seeing) / table.frames : 0.0);
  }
  return s;
}

PoseSetScore pose_set_score(const Layout& layout, const PoseSet& poses, std::span<const PreparedFrame> prepared,
                            std::string label, double phalanx_radius_mm) {
  return pose_set_score(compute_visibility(layout, prepared, phalanx_radius_mm), std::move(label), poses.description);
}

}  // namespace lmc
