#pragma once
// What a calibration found, per controller and for the set: the fitted transform beside the
// nominal one, the size of the correction, residuals per point group before and after, and
// warnings in plain words. A plain value: the CLI prints it, the workbench shows it, tests check it.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "core/calibration/calibration_samples.h"
#include "core/calibration/rigid_transform.h"

namespace lmc {

struct GroupResidual {
  int samples = 0;  // samples the residual is taken over (after the fit's selection)
  double before_mm = std::numeric_limits<double>::quiet_NaN();  // RMS at the nominal transform
  double after_mm = std::numeric_limits<double>::quiet_NaN();   // RMS at the fitted transform
};

struct DeviceCalibration {
  std::string slot;
  int device_id = 0;    // 1-based, as in the recording (LMC1 = 1)
  bool fitted = false;  // false: too little data; `fitted_transform` is the nominal one
  RigidTransform nominal, fitted_transform;
  double moved_mm = 0;    // how far the controller's origin moved
  double turned_deg = 0;  // the rotation between nominal and fitted
  int frames = 0;         // grid frames with at least one usable sample
  // Samples with a coordinate clamped at the controller's axis cut (calibration_samples.h): used
  // through their other coordinates only (counted in `all.samples`), or left out when every
  // coordinate was clamped (`dropped_beyond_cut`, not counted).
  int beyond_cut = 0, dropped_beyond_cut = 0;
  std::array<GroupResidual, kNumPointGroups> groups{};
  GroupResidual all;
  std::vector<std::string> warnings;
};

struct CalibrationResult {
  bool with_vicon = false;
  std::vector<DeviceCalibration> devices;  // one per layout device, in layout order
  std::vector<std::string> warnings;       // about the set (e.g. swapped serials) and the trial
  std::vector<std::string> notes;          // what was done, for the record (not a problem)
  int sweeps = 0;                          // consensus fit iterations (0 with Vicon)
  // Disagreement between controllers on co-visible points: RMS distance of each controller's
  // point from the mean of the other controllers' same point on the same frame.
  double disagreement_before_mm = std::numeric_limits<double>::quiet_NaN();
  double disagreement_after_mm = std::numeric_limits<double>::quiet_NaN();
  int covisible_samples = 0;

  // Every warning, the set's first, then each controller's.
  std::vector<std::string> all_warnings() const;
};

}  // namespace lmc
