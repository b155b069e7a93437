// The verdict's plot series (trial_quality.h, QualityTimeline), read off the same held grid and
// ray-traced labels as the coverage figures, so the plot and the numbers beside it agree.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/session/trial_quality_parts.h"

namespace lmc::trial_quality_detail {

QualityTimeline timeline(const HeldGrid& grid, const std::vector<TracedDevice>& devices, int slices) {
  QualityTimeline out;
  const int n = std::min(std::max(slices, 1), std::max(grid.bins, 1));
  if (grid.bins <= 0 || grid.devices <= 0) return out;
  const double per_slice = static_cast<double>(grid.bins) / n;
  out.slice_s = per_slice * grid.step_us * 1e-6;
  const auto dev_count = static_cast<size_t>(grid.devices);
  for (const auto& d : devices) out.device_ids.push_back(d.device_id);
  out.hand_present.assign(dev_count, std::vector<double>(static_cast<size_t>(n), 0.0));
  out.fingers_seen.assign(dev_count, std::vector<double>(static_cast<size_t>(n), 0.0));
  out.worst_finger_seen_by.assign(static_cast<size_t>(n), std::numeric_limits<double>::quiet_NaN());
  // Each controller's own span, from its first held row to its last: the grid starts with the
  // first row of any controller, and the others' first frames come a frame period or more later.
  // Counted against the whole slice, every line but one started near 0 while the verdict said
  // 100 %; a slice wholly outside the span is a gap (NaN), not "no hand".
  std::vector<int> first_bin(dev_count, grid.bins), last_bin(dev_count, -1);
  for (int b = 0; b < grid.bins; ++b) {
    for (size_t d = 0; d < dev_count; ++d) {
      if (grid.held(b, static_cast<int>(d)) < 0) continue;
      first_bin[d] = std::min(first_bin[d], b);
      last_bin[d] = b;
    }
  }
  for (int s = 0; s < n; ++s) {
    const int b0 = static_cast<int>(std::floor(s * per_slice));
    const int b1 = std::max(b0 + 1, static_cast<int>(std::floor((s + 1) * per_slice)));
    const auto slice = static_cast<size_t>(s);
    int hand_bins = 0;
    double worst_sum = 0;
    for (int b = b0; b < b1 && b < grid.bins; ++b) {
      std::array<int, kNumDigits> seen_by{};
      bool hand = false;
      for (size_t d = 0; d < dev_count; ++d) {
        const int r = grid.held(b, static_cast<int>(d));
        if (r < 0) continue;
        const FingerLabels& labels = devices[d].labels[static_cast<size_t>(r)];
        if (labels[0] < 0) continue;  // no hand in that row
        hand = true;
        out.hand_present[d][slice] += 1.0;
        for (size_t k = 0; k < kNumDigits; ++k) {
          if (labels[k] != 1) continue;
          ++seen_by[k];
          out.fingers_seen[d][slice] += 1.0;
        }
      }
      if (!hand) continue;
      ++hand_bins;
      worst_sum += *std::min_element(seen_by.begin(), seen_by.end());
    }
    for (size_t d = 0; d < dev_count; ++d) {
      const int from = std::max(b0, first_bin[d]), to = std::min({b1, grid.bins, last_bin[d] + 1});
      const double count = static_cast<double>(to - from);
      if (count <= 0) {
        out.hand_present[d][slice] = std::numeric_limits<double>::quiet_NaN();
        out.fingers_seen[d][slice] = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      out.hand_present[d][slice] /= count;
      out.fingers_seen[d][slice] /= count;
    }
    if (hand_bins > 0) out.worst_finger_seen_by[slice] = worst_sum / hand_bins;
  }
  return out;
}

}  // namespace lmc::trial_quality_detail
