#pragma once
// What calibration reads from a trial: every controller's stream on the 100 Hz grid in its own
// coordinates, the ray-traced labels of each grid frame, and optionally the Vicon points (already
// mapped to the controller's 30 points) on the same grid. The stages are the processing chain's
// own (resample.h, visibility_labels.h), so calibration sees exactly what `lmc process` sees.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/hand/hand_track.h"
#include "core/io/lmc_recording.h"
#include "core/io/recorder_sidecar.h"
#include "core/processing/resample.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

struct CalibrationInput {
  GridTrial device_frame;                         // device coordinates, ascending device_id
  std::vector<std::vector<FingerLabels>> labels;  // [device][frame]
  std::optional<HandTrack> vicon;                 // world frame; grid frame f = Vicon frame f
  std::vector<std::string> notes;                 // what was done to line things up
};

struct InputOptions {
  ResampleOptions resample;  // set resample.grid_start_us to line the grid up with Vicon frame 0
  VisibilityParams visibility{400.0, 150.0, 120.0, 10.0};  // recorded-trial analysis (docs/algorithms/visibility.md)
};

// Throws lmc::Error when the recording has no hand at all.
CalibrationInput prepare_calibration_input(const LmcRecording& recording, const HandTrack* vicon,
                                           const InputOptions& options);

// The device-clock time of Vicon frame 0 from a recorder sidecar: the simulator's ground truth
// notes it exactly; a real recording's `vicon_alignment` gives each device's clock at the
// CaptureStart (devices/README.md), of which the median is taken (all controllers share the
// service's clock), plus `delay_ms` (Nexus's trigger Delay). nullopt when the sidecar has neither.
std::optional<std::int64_t> vicon_time_zero_us(const RecorderSidecar& sidecar, double delay_ms = 0.0);

}  // namespace lmc
