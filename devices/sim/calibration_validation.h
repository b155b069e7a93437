#pragma once
// Validation of controller calibration on the simulated rig: seeded cases with random
// translation and rotation errors per controller (sim_config.h), each calibrated with the
// simulator's truth as Vicon and without Vicon, and compared with where the simulated
// controllers really stand. The devices tests run a few cases; `lmc calibrate --validate-sim N`
// runs them all and prints the table.
#include <cstdint>
#include <string>
#include <vector>

#include "core/calibration/calibrate.h"
#include "core/layout/layout.h"
#include "devices/sim/sim_config.h"

namespace lmc::devices {

struct CalibrationValidationOptions {
  int cases = 50;
  std::uint64_t first_seed = 1;
  double max_translation_mm = 80.0;
  double max_rotation_deg = 10.0;
  double seconds = 10.0;  // a still open hand (the simulator's sway included)
  // Limits of the issue: recovered within these after calibration.
  double vicon_limit_mm = 2.0, vicon_limit_deg = 0.5;
  double consensus_limit_mm = 5.0, consensus_limit_deg = 1.0;
};

struct CalibrationValidationCase {
  std::uint64_t seed = 0;
  double injected_mm = 0, injected_deg = 0;         // largest injected error of any controller
  double vicon_mm = 0, vicon_deg = 0;               // largest error left, with Vicon truth
  double consensus_mm = 0, consensus_deg = 0;       // without Vicon, relative to the anchor
  double vicon_seconds = 0, consensus_seconds = 0;  // calibrate() alone, wall time
  bool vicon_ok = false, consensus_ok = false;
  // Controllers the calibration left as they were (their injected error took the hand out of their
  // view, so they have no samples): not scored, counted here and named in `warnings`.
  int vicon_unfitted = 0, consensus_unfitted = 0;
  std::vector<std::string> warnings;  // any warning is unexpected here
};

// Sim configuration of case `seed`: the defaults, a still open hand, random calibration errors.
SimConfig validation_sim_config(std::uint64_t seed, const CalibrationValidationOptions& options);

// One case: records the simulated trial, calibrates it both ways and measures what is left.
CalibrationValidationCase run_calibration_case(const Layout& layout, std::uint64_t seed,
                                               const CalibrationValidationOptions& options);
// The same with a rig of the caller's (e.g. the Devices tab capture's errors per slot); `config`'s
// own seed and errors are used, options' error sizes are not.
CalibrationValidationCase run_calibration_case(const Layout& layout, const SimConfig& config,
                                               const CalibrationValidationOptions& options);

// The calibration of a trial recorded with `layout` against the same layout with two slots'
// poses exchanged (their serials swapped): the result's set-level warnings.
std::vector<std::string> swapped_serial_warnings(const Layout& layout, int slot_a, int slot_b, std::uint64_t seed,
                                                 bool with_vicon);

// A Markdown table of the cases with a summary line (worst case, how many within the limits).
std::string validation_table(const std::vector<CalibrationValidationCase>& cases,
                             const CalibrationValidationOptions& options);

}  // namespace lmc::devices
