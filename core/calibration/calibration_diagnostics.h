#pragma once
// Residuals and the warnings a person reads after a calibration (calibration_result.h).
#include <array>
#include <string>
#include <vector>

#include "core/calibration/calibration_result.h"

namespace lmc {

// Sums squared residuals per point group.
struct ResidualSums {
  std::array<double, kNumPointGroups> squares{};
  std::array<int, kNumPointGroups> counts{};

  void add(int group, double residual_mm) {
    squares[static_cast<size_t>(group)] += residual_mm * residual_mm;
    ++counts[static_cast<size_t>(group)];
  }
  double rms(int group) const;  // NaN without samples
  double rms_all() const;
  int count_all() const;
};

struct WarningThresholds {
  double max_moved_mm = 100.0;  // a larger correction is not a misplaced controller
  double max_turned_deg = 20.0;
  double high_residual_mm = 8.0;  // RMS after calibration above this "stays high"
  // Two controllers look swapped when each one's fitted transform is at most this fraction as far
  // from the other's nominal transform as from its own, and its own correction is large.
  double swap_ratio = 0.5;
  double swap_min_correction_mm = 30.0;
};

// Distance between two transforms in mm: the larger of the origin's movement and the rotation
// seen at 100 mm (a hand's distance from the controller).
double transform_distance_mm(const RigidTransform& a, const RigidTransform& b);

// Fills each device's warnings (too little data, implausible correction, residual still high)
// and the set's (swapped serials). Expects moved/turned/residuals to be set.
void add_warnings(CalibrationResult& result, const WarningThresholds& thresholds);

}  // namespace lmc
