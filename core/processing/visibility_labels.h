#pragma once
// Stage 3 (docs/algorithms/visibility.md, "for recorded data"): per device and grid frame, which
// fingers the device could really see. The placement engine's ray tracer runs on the device's
// own, not yet realigned, points with the device at the origin and identity rotation and the
// recorded-trial range (400 mm, 150°×120°, phalanx radius 10 mm). Labels: 1 visible, 0 reported
// but hidden (the value came from the controller's internal model), −1 no hand.
#include <vector>

#include "core/hand/hand_track.h"
#include "core/io/lmc_recording.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

// The recorded-trial analysis parameters (docs/algorithms/visibility.md).
VisibilityParams recorded_trial_visibility_params();

std::vector<FingerLabels> visibility_labels(const HandTrack& device_frame_track,
                                            const VisibilityParams& params = recorded_trial_visibility_params());

// The per-frame rule behind visibility_labels, shared with the online fuser (online_fusion.h) so
// live and offline labels cannot drift apart: `frame` is prepared from the device-frame points,
// `hand` says whether the row has a hand (the palm position is finite), `limits` =
// make_limits(params).
FingerLabels frame_visibility_labels(const PreparedFrame& frame, bool hand, const VisibilityLimits& limits);

}  // namespace lmc
