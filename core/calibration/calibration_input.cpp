#include "core/calibration/calibration_input.h"

#include <algorithm>

#include "core/common/error.h"
#include "core/processing/visibility_labels.h"

namespace lmc {

CalibrationInput prepare_calibration_input(const LmcRecording& recording, const HandTrack* vicon,
                                           const InputOptions& options) {
  if (recording.rows.empty()) throw Error(ErrorLocation(recording.source), "the LMC recording has no data rows");
  CalibrationInput in;
  if (recording.kind == RecordingKind::kRaw) {
    ResampleReport report;
    in.device_frame = resample_recording(recording, options.resample, &report);
    for (const auto& line : report.summary_lines()) in.notes.push_back(line);
    if (options.resample.grid_start_us) in.notes.push_back("grid lined up with Vicon frame 0 from the sidecar");
  } else {
    in.device_frame = grid_from_resampled(recording, &in.notes);
  }
  if (in.device_frame.frame_count == 0)
    throw Error(ErrorLocation(recording.source), "no controller saw a hand in this recording");
  in.labels.reserve(in.device_frame.devices.size());
  for (const auto& d : in.device_frame.devices) in.labels.push_back(visibility_labels(d.track, options.visibility));
  if (vicon != nullptr) in.vicon = *vicon;
  return in;
}

std::optional<std::int64_t> vicon_time_zero_us(const RecorderSidecar& sidecar, double delay_ms) {
  if (sidecar.ground_truth) return sidecar.ground_truth->device_clock_at_time_zero_us;
  const auto& align = sidecar.vicon_alignment;
  if (!align.is_object() || !align.contains("devices") || !align["devices"].is_array()) return std::nullopt;
  std::vector<std::int64_t> clocks;
  for (const auto& d : align["devices"])
    if (d.is_object() && d.contains("device_clock_at_event_us") && d["device_clock_at_event_us"].is_number())
      clocks.push_back(d["device_clock_at_event_us"].get<std::int64_t>());
  if (clocks.empty()) return std::nullopt;
  std::sort(clocks.begin(), clocks.end());
  return clocks[clocks.size() / 2] + static_cast<std::int64_t>(delay_ms * 1000.0);
}

}  // namespace lmc
