#pragma once
// The four numbers of the visibility test (docs/algorithms/visibility.md): sensor range, the
// pyramid's full angles along the device's long (x) and short (z) axes, and the phalanx radius.
// Defaults: the study's optimisation values (600 mm, 150°×120°, 10 mm radius); recorded trials
// are analysed with 400 mm.
#include "core/layout/sensor_model.h"

namespace lmc {

struct VisibilityParams {
  double range_mm = 600.0;
  double fov_long_deg = 150.0;
  double fov_short_deg = 120.0;
  double phalanx_radius_mm = 10.0;
  double axis_cut_mm = 250.0;  // the robust metric's cut (layout_tally.h), the study's value
  double range_near_mm = 0.0;  // nothing closer is tracked (0: no near limit, as in the study)

  static VisibilityParams from_sensor(const SensorModel& s, double phalanx_radius_mm = 10.0) {
    return {s.range_mm, s.fov_long_deg, s.fov_short_deg, phalanx_radius_mm, s.axis_cut_mm, s.range_near_mm};
  }
  bool operator==(const VisibilityParams&) const = default;
};

// Precomputed form used by the kernels (tangents of the half angles, squared range and radius).
struct VisibilityLimits {
  double range_mm = 0;
  double range_sq = 0;
  // The largest squared distance whose correctly rounded square root is ≤ range_mm, so that
  // |v|² > range_sq_exact decides exactly as sqrt(|v|²) > range_mm (the authors' comparison, ties
  // included) without the square root: the batch kernel's test vectorises without it.
  double range_sq_exact = 0;
  double tan_half_long = 0;
  double tan_half_short = 0;
  double radius_sq = 0;
  double axis_cut_mm = 250.0;  // carried for the robust metric's per-device cut; the kernel does not use it
  double range_near_sq = 0;    // |v|² below this is too near to track (0: never)
};
VisibilityLimits make_limits(const VisibilityParams& p);

}  // namespace lmc
