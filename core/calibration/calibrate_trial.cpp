#include "core/calibration/calibrate_trial.h"

#include <cmath>

#include "core/calibration/calibrated_layout.h"
#include "core/calibration/calibration_input.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/io/lmc_recording.h"
#include "core/io/recorder_sidecar.h"
#include "core/io/vicon_mapping.h"
#include "core/processing/batch.h"

namespace lmc {
namespace {

namespace fs = std::filesystem;

HandTrack load_vicon_track(const fs::path& path, const fs::path& mapping_path) {
  const MarkerSeries markers = load_vicon_markers(path);
  // The calibration grid is the LMC's 100 Hz grid and Vicon frame f is grid frame f.
  if (std::abs(markers.rate_hz - 100.0) > 0.5) {
    throw Error(ErrorLocation(path.string()), "Vicon rate is " + format_fixed(markers.rate_hz, 2) +
                                                  " Hz; calibration expects 100 Hz like the LMC grid");
  }
  const ViconMapping mapping = mapping_path.empty() ? default_vicon_mapping() : load_vicon_mapping(mapping_path);
  return apply_vicon_mapping(mapping, markers);
}

}  // namespace

TrialCalibration calibrate_trial(const TrialCalibrationRequest& request, const Layout& nominal) {
  const fs::path& trial = request.trial;
  if (!fs::exists(trial)) throw Error(ErrorLocation(trial.string()), "no such file");
  if (fs::is_directory(trial)) throw Error(ErrorLocation(trial.string()), "is a folder; give one LMC recording file");
  if (request.vicon && !fs::is_regular_file(*request.vicon)) {
    throw Error(ErrorLocation(request.vicon->string()), "no such Vicon file (.trc or .c3d)");
  }
  TrialCalibration out;
  const TrialSources job = discover_trials(trial, request.vicon).front();
  out.trial = job.trial;
  if (!request.vicon && job.vicon) {
    out.notes.push_back(job.vicon->string() +
                        " lies next to the trial; calibrating without it (give it as the Vicon file to use it)");
  }

  const LmcRecording rec = read_lmc_recording(trial);
  for (const auto& w : rec.warnings) out.file_warnings.push_back(trial.string() + ": " + w);
  std::optional<HandTrack> vicon;
  if (request.vicon) vicon = load_vicon_track(*request.vicon, request.mapping);
  InputOptions options;
  if (vicon && job.sidecar) {
    const RecorderSidecar side = read_recorder_sidecar(*job.sidecar);
    options.resample.grid_start_us = vicon_time_zero_us(side, request.vicon_delay_ms);
    if (!options.resample.grid_start_us) {
      out.notes.push_back(job.sidecar->string() + " has no Vicon alignment: the grid starts at the first hand sample");
    }
  }
  const CalibrationInput input = prepare_calibration_input(rec, vicon ? &*vicon : nullptr, options);
  for (const auto& n : input.notes) out.notes.push_back(n);
  try {
    CalibrationOptions copt;
    copt.anchor_vicon_to_layout = request.anchor_to_layout;
    out.result = calibrate(input, nominal, copt);
  } catch (const Error& e) {
    throw Error(ErrorLocation(trial.string()), e.what());
  }
  out.calibrated = calibrated_layout(
      nominal, out.result, {job.trial, request.vicon ? request.vicon->string() : std::string(), request.when_utc});
  return out;
}

}  // namespace lmc
