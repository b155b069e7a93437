#include "core/geometry/palm_hull.h"

#include <Eigen/Geometry>  // cross products; no decomposition here
#include <algorithm>
#include <cmath>

namespace lmc {
namespace {

// Relative size below which a cross product counts as zero (collinear / coplanar points).
constexpr double kDegenerateRel = 1e-12;

// The largest distance between two of the points. One square root of the largest squared
// distance: the square root is correctly rounded and never decreasing, so this is, to the bit, the
// largest of the distances (and each pair is measured once, not twice).
double extent_of(std::span<const Eigen::Vector3d> pts) {
  double e2 = 0.0;
  for (size_t i = 0; i < pts.size(); ++i) {
    for (size_t j = i + 1; j < pts.size(); ++j) e2 = std::max(e2, (pts[i] - pts[j]).squaredNorm());
  }
  return std::sqrt(e2);
}

// Which sides of the plane through `origin` with unit normal `nrm` the points lie on, beyond
// `tolerance`: a facet (or a polygon edge) has every point on one side.
struct Sides {
  bool positive = false, negative = false;
};
Sides sides_of(const Eigen::Vector3d& nrm, const Eigen::Vector3d& origin, std::span<const Eigen::Vector3d> pts,
               double tolerance) {
  Sides sides;
  const double d = nrm.dot(origin);
  for (const auto& p : pts) {
    const double s = nrm.dot(p) - d;
    if (s > tolerance) sides.positive = true;
    if (s < -tolerance) sides.negative = true;
    if (sides.positive && sides.negative) break;  // a plane through the middle: nothing more to learn
  }
  return sides;
}

// Adds the plane through `origin`, its normal turned to face away from the points (all of them
// then satisfy n·p ≤ d), while there is room.
void add_outward_plane(ConvexHull6& hull, Eigen::Vector3d nrm, const Eigen::Vector3d& origin, const Sides& sides) {
  if (sides.positive) nrm = -nrm;
  if (hull.plane_count < ConvexHull6::kMaxPlanes) {
    hull.planes[static_cast<size_t>(hull.plane_count++)] = {nrm.x(), nrm.y(), nrm.z(), nrm.dot(origin)};
  }
}

}  // namespace

ConvexHull6 build_convex_hull(std::span<const Eigen::Vector3d> points) {
  ConvexHull6 hull;
  const size_t n = std::min(points.size(), static_cast<size_t>(ConvexHull6::kMaxPoints));
  const std::span<const Eigen::Vector3d> pts = points.first(n);
  if (n < 3) {
    hull.degenerate = true;
    return hull;
  }
  const double extent = extent_of(pts);
  if (!(extent > 0.0) || !std::isfinite(extent)) {
    hull.degenerate = true;
    return hull;
  }
  // Side tolerance for "all other points are behind this plane": relative to the hull's size.
  const double side_tol = 1e-9 * extent;

  // 3-D case: every triple whose plane has all other points on one side is a facet (coplanar
  // facets with four points appear several times; duplicates are harmless).
  bool any_nondegenerate_triple = false;
  Eigen::Vector3d some_normal = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      for (size_t k = j + 1; k < n; ++k) {
        Eigen::Vector3d nrm = (pts[j] - pts[i]).cross(pts[k] - pts[i]);
        const double len = nrm.norm();
        if (len <= kDegenerateRel * extent * extent) continue;  // collinear triple
        any_nondegenerate_triple = true;
        nrm /= len;
        some_normal = nrm;
        const Sides sides = sides_of(nrm, pts[i], pts, side_tol);
        if (sides.positive && sides.negative) continue;    // a plane through the middle, not a facet
        if (!sides.positive && !sides.negative) continue;  // all coplanar: handled below
        add_outward_plane(hull, nrm, pts[i], sides);
      }
    }
  }
  if (!any_nondegenerate_triple) {
    hull.degenerate = true;  // all points collinear
    return hull;
  }
  if (hull.plane_count > 0) return hull;

  // Coplanar points: the hull is a convex polygon in their plane. Its edges become planes that
  // contain the polygon normal, so a query (which lies on the palm plane by construction) is
  // inside when it is behind every edge plane.
  hull.flat = true;
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      const Eigen::Vector3d edge = pts[j] - pts[i];
      if (edge.norm() <= kDegenerateRel * extent) continue;
      Eigen::Vector3d nrm = edge.cross(some_normal);
      const double len = nrm.norm();
      if (len <= 0.0) continue;
      nrm /= len;
      const Sides sides = sides_of(nrm, pts[i], pts, side_tol);
      if (sides.positive && sides.negative) continue;
      add_outward_plane(hull, nrm, pts[i], sides);
    }
  }
  // A flat hull is only the polygon itself: also require the query to lie on its plane (within
  // a tolerance), expressed as two opposite planes.
  const double d0 = some_normal.dot(pts[0]);
  if (hull.plane_count + 2 <= ConvexHull6::kMaxPlanes) {
    const double slack = 1e-6 * extent;  // the palm-plane intersection is computed, not exact
    hull.planes[static_cast<size_t>(hull.plane_count++)] = {some_normal.x(), some_normal.y(), some_normal.z(),
                                                            d0 + slack};
    hull.planes[static_cast<size_t>(hull.plane_count++)] = {-some_normal.x(), -some_normal.y(), -some_normal.z(),
                                                            -d0 + slack};
  }
  return hull;
}

}  // namespace lmc
