#include "core/processing/visibility_labels.h"

#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc {

VisibilityParams recorded_trial_visibility_params() { return VisibilityParams{400.0, 150.0, 120.0, 10.0}; }

std::vector<FingerLabels> visibility_labels(const HandTrack& track, const VisibilityParams& params) {
  const int n = track.frame_count;
  std::vector<HandFrame> frames(static_cast<size_t>(n));
  for (int f = 0; f < n; ++f) {
    HandFrame& hf = frames[static_cast<size_t>(f)];
    hf.hand_present = track.has_hand(f);
    for (int i = 0; i < kNumHandPoints; ++i) hf.point(i) = track.at(f, i);
  }
  const std::vector<PreparedFrame> prepared = prepare_frames(frames);
  std::vector<FingerBits> bits(static_cast<size_t>(n));
  device_visibility(DeviceView::identity(), prepared, make_limits(params), bits);
  std::vector<FingerLabels> labels(static_cast<size_t>(n));
  for (int f = 0; f < n; ++f) {
    auto& row = labels[static_cast<size_t>(f)];
    const bool hand = frames[static_cast<size_t>(f)].hand_present;
    for (int k = 0; k < kNumDigits; ++k) {
      row[static_cast<size_t>(k)] =
          hand ? static_cast<std::int8_t>((bits[static_cast<size_t>(f)] >> k) & 1) : static_cast<std::int8_t>(-1);
    }
  }
  return labels;
}

}  // namespace lmc
