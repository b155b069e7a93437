#include "core/geometry/palm_hull.h"

#include <Eigen/Geometry>  // cross products; no decomposition here
#include <algorithm>
#include <cmath>

namespace lmc {
namespace {

// Relative size below which a cross product counts as zero (collinear / coplanar points).
constexpr double kDegenerateRel = 1e-12;

double extent_of(std::span<const Eigen::Vector3d> pts) {
  double e = 0.0;
  for (const auto& a : pts) {
    for (const auto& b : pts) e = std::max(e, (a - b).norm());
  }
  return e;
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
        const double d = nrm.dot(pts[i]);
        bool pos = false, neg = false;
        for (size_t m = 0; m < n; ++m) {
          const double s = nrm.dot(pts[m]) - d;
          if (s > side_tol) pos = true;
          if (s < -side_tol) neg = true;
        }
        if (pos && neg) continue;   // a plane through the middle, not a facet
        if (!pos && !neg) continue; // all coplanar: handled below
        if (pos) {                  // orient outwards: all points satisfy n·p ≤ d
          nrm = -nrm;
        }
        if (hull.plane_count < ConvexHull6::kMaxPlanes) {
          hull.planes[static_cast<size_t>(hull.plane_count++)] = {nrm.x(), nrm.y(), nrm.z(), nrm.dot(pts[i])};
        }
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
      const double d = nrm.dot(pts[i]);
      bool pos = false, neg = false;
      for (size_t m = 0; m < n; ++m) {
        const double s = nrm.dot(pts[m]) - d;
        if (s > side_tol) pos = true;
        if (s < -side_tol) neg = true;
      }
      if (pos && neg) continue;
      if (pos) nrm = -nrm;
      if (hull.plane_count < ConvexHull6::kMaxPlanes) {
        hull.planes[static_cast<size_t>(hull.plane_count++)] = {nrm.x(), nrm.y(), nrm.z(), nrm.dot(pts[i])};
      }
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
