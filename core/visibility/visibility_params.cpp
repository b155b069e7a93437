#include "core/visibility/visibility_params.h"

#include <cmath>
#include <numbers>

namespace lmc {

VisibilityLimits make_limits(const VisibilityParams& p) {
  const double deg = std::numbers::pi / 180.0;
  VisibilityLimits l;
  l.range_sq = p.range_mm * p.range_mm;
  l.range_mm = p.range_mm;
  l.tan_half_long = std::tan(0.5 * p.fov_long_deg * deg);
  l.tan_half_short = std::tan(0.5 * p.fov_short_deg * deg);
  l.radius_sq = p.phalanx_radius_mm * p.phalanx_radius_mm;
  return l;
}

}  // namespace lmc
