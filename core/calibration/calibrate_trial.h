#pragma once
// One calibration trial file, end to end: read the LMC recording, optionally the Vicon file (mapped
// to the controller's points, clocks lined up from the recorder sidecar), calibrate against the
// layout the trial was recorded with, and write the result back into a layout. The one sequence
// `lmc calibrate` and the workbench's Calibrate step both run, so they cannot drift apart.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/calibration/calibrate.h"
#include "core/calibration/calibration_result.h"
#include "core/layout/layout.h"

namespace lmc {

struct TrialCalibrationRequest {
  std::filesystem::path trial;                 // an LMC recording (raw or resampled)
  std::optional<std::filesystem::path> vicon;  // .trc/.c3d of the same trial; none: consensus fit
  std::filesystem::path mapping;               // Vicon → LMC point mapping; empty: the default one
  double vicon_delay_ms = 0.0;                 // Nexus's trigger Delay, added to the sidecar's alignment
  bool anchor_to_layout = false;               // with Vicon: keep the layout's world frame
  std::string when_utc;                        // written into the calibrated layout's description
};

struct TrialCalibration {
  std::string trial;  // the trial's name (file name without the LMC_ prefix and suffix)
  CalibrationResult result;
  Layout calibrated;                       // `nominal` with every fitted controller corrected (calibrated_layout.h)
  std::vector<std::string> file_warnings;  // what reading the recording found wrong (file: problem)
  std::vector<std::string> notes;          // what was done to line things up, files left out
};

// Throws lmc::Error naming the file at fault (a missing trial or Vicon file, a Vicon rate other
// than 100 Hz, a trial without a hand).
TrialCalibration calibrate_trial(const TrialCalibrationRequest& request, const Layout& nominal);

}  // namespace lmc
