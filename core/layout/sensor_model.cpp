#include "core/layout/sensor_model.h"

#include <cmath>

namespace lmc {

std::string sensor_problem(const SensorModel& s) {
  if (!std::isfinite(s.range_mm) || s.range_mm <= 0 || s.range_mm > 5000) {
    return "range_mm: must be a finite number in (0, 5000]";
  }
  if (!std::isfinite(s.range_near_mm) || s.range_near_mm < 0 || s.range_near_mm >= s.range_mm) {
    return "range_near_mm: must be a finite number in [0, range_mm)";
  }
  if (!std::isfinite(s.fov_long_deg) || s.fov_long_deg <= 0 || s.fov_long_deg >= 180) {
    return "fov_long_deg: must be in (0, 180)";
  }
  if (!std::isfinite(s.fov_short_deg) || s.fov_short_deg <= 0 || s.fov_short_deg >= 180) {
    return "fov_short_deg: must be in (0, 180)";
  }
  if (!std::isfinite(s.axis_cut_mm) || s.axis_cut_mm <= 0 || s.axis_cut_mm > 5000) {
    return "axis_cut_mm: must be a finite number in (0, 5000]";
  }
  return {};
}

SensorModel apply_overrides(SensorModel base, const SensorOverrides& o) {
  if (o.range_mm) base.range_mm = *o.range_mm;
  if (o.range_near_mm) base.range_near_mm = *o.range_near_mm;
  if (o.fov_long_deg) base.fov_long_deg = *o.fov_long_deg;
  if (o.fov_short_deg) base.fov_short_deg = *o.fov_short_deg;
  if (o.axis_cut_mm) base.axis_cut_mm = *o.axis_cut_mm;
  return base;
}

SensorOverrides overrides_between(const SensorModel& base, const SensorModel& effective) {
  SensorOverrides o;
  if (effective.range_mm != base.range_mm) o.range_mm = effective.range_mm;
  if (effective.range_near_mm != base.range_near_mm) o.range_near_mm = effective.range_near_mm;
  if (effective.fov_long_deg != base.fov_long_deg) o.fov_long_deg = effective.fov_long_deg;
  if (effective.fov_short_deg != base.fov_short_deg) o.fov_short_deg = effective.fov_short_deg;
  if (effective.axis_cut_mm != base.axis_cut_mm) o.axis_cut_mm = effective.axis_cut_mm;
  return o;
}

}  // namespace lmc
