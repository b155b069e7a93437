#pragma once
// What one controller can see: a pyramid with its apex at the device origin, opening upwards
// (device +y), spread along the long axis x and the short axis z, cut at a range.
// Defaults are the study's optimisation values (docs/algorithms/visibility.md): 600 mm, 150°×120°.
// Recorded-trial analysis uses 400 mm.
namespace lmc {

struct SensorModel {
  double range_mm = 600.0;
  double fov_long_deg = 150.0;   // full angle along x (long axis, camera baseline)
  double fov_short_deg = 120.0;  // full angle along z

  bool operator==(const SensorModel&) const = default;
};

}  // namespace lmc
