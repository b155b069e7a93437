#include "core/processing/visibility_labels.h"

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
  std::vector<HandFrame> frames(static_cast<size_t>(n));
  for (int f = 0; f < n; ++f) {
    HandFrame& hf = frames[static_cast<size_t>(f)];
    hf.hand_present = track.has_hand(f);
    for (int i = 0; i < kNumHandPoints; ++i) hf.point(i) = track.at(f, i);
  }
  const std::vector<PreparedFrame> prepared = prepare_frames(frames);  // in parallel
  const VisibilityLimits limits = make_limits(params);
  std::vector<FingerLabels> labels(static_cast<size_t>(n));
  for (int f = 0; f < n; ++f) {
    const auto i = static_cast<size_t>(f);
    labels[i] = frame_visibility_labels(prepared[i], frames[i].hand_present, limits);
  }
  return labels;
}

}  // namespace lmc
