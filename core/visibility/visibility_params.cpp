#include "core/visibility/visibility_params.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace lmc {
namespace {

// sqrt is correctly rounded and monotone, so {x : sqrt(x) > L} is {x : x > T} for
// T = max{x : sqrt(x) ≤ L}. Start from L² (within an ulp or two of T) and step to it.
double largest_square_within(double range) {
  const double inf = std::numeric_limits<double>::infinity();
  if (std::isnan(range)) return range;  // sqrt(x) > NaN never holds, and neither does x > NaN
  if (range < 0.0) return -inf;         // every non-NaN x is out of range
  if (range == inf) return inf;
  double t = range * range;
  if (!std::isfinite(t)) t = std::numeric_limits<double>::max();
  while (std::sqrt(t) > range) t = std::nextafter(t, -inf);
  while (t < inf && std::sqrt(std::nextafter(t, inf)) <= range) t = std::nextafter(t, inf);
  return t;
}

}  // namespace

VisibilityLimits make_limits(const VisibilityParams& p) {
  const double deg = std::numbers::pi / 180.0;
  VisibilityLimits l;
  l.range_sq = p.range_mm * p.range_mm;
  l.range_mm = p.range_mm;
  l.range_sq_exact = largest_square_within(p.range_mm);
  l.tan_half_long = std::tan(0.5 * p.fov_long_deg * deg);
  l.tan_half_short = std::tan(0.5 * p.fov_short_deg * deg);
  l.radius_sq = p.phalanx_radius_mm * p.phalanx_radius_mm;
  l.axis_cut_mm = p.axis_cut_mm;
  l.range_near_sq = p.range_near_mm * p.range_near_mm;
  return l;
}

}  // namespace lmc
