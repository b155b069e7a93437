#pragma once
// Stage 3 (reference-algorithms.md §3, "for recorded data"): per device and grid frame, which
// fingers the device could really see. The placement engine's ray tracer runs on the device's
// own, not yet realigned, points with the device at the origin and identity rotation and the
// recorded-trial range (400 mm, 150°×120°, phalanx radius 10 mm). Labels: 1 visible, 0 reported
// but hidden (the value came from the controller's internal model), −1 no hand.
#include <vector>

#include "core/io/lmc_recording.h"
#include "core/processing/hand_track.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

// The recorded-trial analysis parameters of §3.
VisibilityParams recorded_trial_visibility_params();

std::vector<FingerLabels> visibility_labels(const HandTrack& device_frame_track,
                                            const VisibilityParams& params = recorded_trial_visibility_params());

}  // namespace lmc
