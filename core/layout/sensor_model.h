#pragma once
// What one controller can see: a pyramid with its apex at the device origin, opening upwards
// (device +y), spread along the long axis x and the short axis z, between a near and a far range,
// plus the axis cut (the coordinate beyond which the controller clips what it reports).
// Defaults are the study's optimisation values (docs/algorithms/visibility.md): 600 mm, 150°×120°,
// no near limit, a 250 mm cut: the catalogue's "study" entry (assets/sensors/sensors.json).
// Recorded-trial analysis uses 400 mm.
#include <optional>
#include <string>

namespace lmc {

struct SensorModel {
  double range_mm = 600.0;       // far limit of the pyramid
  double range_near_mm = 0.0;    // nothing closer than this is tracked
  double fov_long_deg = 150.0;   // full angle along x (long axis, camera baseline)
  double fov_short_deg = 120.0;  // full angle along z
  double axis_cut_mm = 250.0;    // a seen marker beyond ±cut on a device axis is clipped (robust metric)

  bool operator==(const SensorModel&) const = default;
};

// The fields of a SensorModel a layout device sets apart from its catalogue model; unset ones
// take the model's value.
struct SensorOverrides {
  std::optional<double> range_mm;
  std::optional<double> range_near_mm;
  std::optional<double> fov_long_deg;
  std::optional<double> fov_short_deg;
  std::optional<double> axis_cut_mm;

  bool empty() const { return !range_mm && !range_near_mm && !fov_long_deg && !fov_short_deg && !axis_cut_mm; }
  bool operator==(const SensorOverrides&) const = default;
};

// The first problem of a sensor model as "field: problem" (field names as in layout files:
// "range_mm", "fov_long_deg", …), or "" when it is sane: ranges finite with 0 ≤ near < far ≤ 5000,
// angles in (0, 180), cut in (0, 5000].
std::string sensor_problem(const SensorModel& s);

// `base` with the set fields of `overrides` in place.
SensorModel apply_overrides(SensorModel base, const SensorOverrides& overrides);
// The fields in which `effective` differs from `base` (what a layout file stores per device).
SensorOverrides overrides_between(const SensorModel& base, const SensorModel& effective);

}  // namespace lmc
