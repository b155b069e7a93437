#include "core/processing/visibility_labels.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc {

VisibilityParams recorded_trial_visibility_params() {
  return VisibilityParams{400.0, 150.0, 120.0, 10.0};
}

FingerLabels frame_visibility_labels(const PreparedFrame& frame, bool hand, const VisibilityLimits& limits) {
  FingerLabels row;
  if (!hand) {
    row.fill(-1);
    return row;
  }
  const FingerBits bits = visible_fingers(frame, DeviceView::identity(), limits);
  for (int k = 0; k < kNumDigits; ++k) row[static_cast<size_t>(k)] = static_cast<std::int8_t>((bits >> k) & 1);
  return row;
}

std::vector<FingerLabels> visibility_labels(const HandTrack& track, const VisibilityParams& params) {
  const int n = track.frame_count;
  const VisibilityLimits limits = make_limits(params);
  std::vector<FingerLabels> labels(static_cast<size_t>(n));
  // Each frame is prepared and labelled where it is used. A prepared frame is 2 KB: a trial's
  // worth of them, written out and read back, cost more than the labels themselves. Every frame's
  // label depends on that frame alone, so the result is the same for any thread count.
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 64), [&](const tbb::blocked_range<int>& r) {
    PreparedFrame prepared;
    for (int f = r.begin(); f != r.end(); ++f) {
      const bool hand = track.has_hand(f);
      prepare_frame_into(std::span<const Vec3, kNumHandPoints>(
                             track.points.data() + static_cast<size_t>(f) * kNumHandPoints, kNumHandPoints),
                         hand, prepared);
      labels[static_cast<size_t>(f)] = frame_visibility_labels(prepared, hand, limits);
    }
  });
  return labels;
}

}  // namespace lmc
