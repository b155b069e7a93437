#include "core/calibration/calibration_diagnostics.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/common/angles.h"
#include "core/common/number_format.h"

namespace lmc {

double ResidualSums::rms(int group) const {
  const int n = counts[static_cast<size_t>(group)];
  return n == 0 ? std::numeric_limits<double>::quiet_NaN() : std::sqrt(squares[static_cast<size_t>(group)] / n);
}

double ResidualSums::rms_all() const {
  double s = 0;
  for (const double v : squares) s += v;
  const int n = count_all();
  return n == 0 ? std::numeric_limits<double>::quiet_NaN() : std::sqrt(s / n);
}

int ResidualSums::count_all() const {
  int n = 0;
  for (const int c : counts) n += c;
  return n;
}

double transform_distance_mm(const RigidTransform& a, const RigidTransform& b) {
  const double turn_rad = rotation_angle_deg(a.r.transpose() * b.r) * kRadPerDeg;
  return std::max((a.t - b.t).norm(), 100.0 * turn_rad);
}

std::vector<std::string> CalibrationResult::all_warnings() const {
  std::vector<std::string> out = warnings;
  for (const auto& d : devices) out.insert(out.end(), d.warnings.begin(), d.warnings.end());
  return out;
}

void add_warnings(CalibrationResult& result, const WarningThresholds& th) {
  const char* against = result.with_vicon ? "from the Vicon points" : "from the other controllers";
  for (auto& d : result.devices) {
    if (!d.fitted) continue;
    if (d.moved_mm > th.max_moved_mm || d.turned_deg > th.max_turned_deg) {
      d.warnings.push_back(d.slot + ": the correction (" + format_fixed(d.moved_mm, 1) + " mm, " +
                           format_fixed(d.turned_deg, 1) +
                           "°) is larger than a misplaced controller explains (limits " +
                           format_fixed(th.max_moved_mm, 0) + " mm, " + format_fixed(th.max_turned_deg, 0) +
                           "°): check that the right controller is in this slot and its nominal pose");
    }
    if (std::isfinite(d.all.after_mm) && d.all.after_mm > th.high_residual_mm) {
      d.warnings.push_back(
          d.slot + ": its points stay " + format_fixed(d.all.after_mm, 1) + " mm RMS " + against +
          " after calibration (above " + format_fixed(th.high_residual_mm, 0) +
          " mm): the hand moved too much, the controller tracked it poorly, or the clocks are not lined up");
    }
  }
  // Swapped serials: each of two controllers ends up where the other was meant to stand.
  for (size_t a = 0; a < result.devices.size(); ++a) {
    for (size_t b = a + 1; b < result.devices.size(); ++b) {
      const auto& da = result.devices[a];
      const auto& db = result.devices[b];
      if (!da.fitted || !db.fitted) continue;
      const double own_a = transform_distance_mm(da.fitted_transform, da.nominal);
      const double own_b = transform_distance_mm(db.fitted_transform, db.nominal);
      const double cross_a = transform_distance_mm(da.fitted_transform, db.nominal);
      const double cross_b = transform_distance_mm(db.fitted_transform, da.nominal);
      if (own_a > th.swap_min_correction_mm && own_b > th.swap_min_correction_mm && cross_a < th.swap_ratio * own_a &&
          cross_b < th.swap_ratio * own_b) {
        result.warnings.push_back(
            da.slot + " and " + db.slot + " look swapped: each controller was found " + format_fixed(cross_a, 0) +
            " / " + format_fixed(cross_b, 0) + " mm from the other's nominal place but " + format_fixed(own_a, 0) +
            " / " + format_fixed(own_b, 0) +
            " mm from its own. Swap their serials in the layout (or the controllers) and calibrate again");
      }
    }
  }
}

}  // namespace lmc
