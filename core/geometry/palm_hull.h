#pragma once
// Membership in the convex hull of a handful of points (the six palm points of
// docs/algorithms/visibility.md). The authors decide "q lies in the hull" with a linear programme
// (q is a convex combination of the points); we precompute the hull's facet planes once per frame
// so that each query is a few dot products, and fall back to the in-plane polygon when the points
// are coplanar (the LP then accepts exactly the points of that polygon).
#include <Eigen/Core>
#include <array>
#include <span>

namespace lmc {

// A facet plane n·p ≤ d (n unit length, pointing out of the hull).
struct HullPlane {
  double nx = 0, ny = 0, nz = 0, d = 0;
};

// Up to C(6,3) = 20 candidate facets for 6 points (coplanar sets become in-plane edge planes,
// at most C(6,2) = 15). Fixed capacity: no allocation per frame.
struct ConvexHull6 {
  static constexpr int kMaxPoints = 6;
  static constexpr int kMaxPlanes = 20;
  std::array<HullPlane, kMaxPlanes> planes{};
  int plane_count = 0;
  bool flat = false;        // the points are coplanar: planes are the polygon's edges
  bool degenerate = false;  // fewer than 3 non-collinear points: nothing is inside (except on it)

  // Points on a facet count as inside, like a feasible LP; `tolerance_mm` absorbs rounding.
  static constexpr double kTolerance_mm = 1e-7;
};

// How the 20 candidate facets of six points are computed: four at a time with AVX2 where the CPU
// has it (kFastest), or one by one (kPlain). Both give the same planes bit for bit (the same IEEE
// operations in the same order per facet; tests compare them).
enum class HullBuild { kFastest, kPlain };

// Builds the facet planes of the hull of 3 to 6 points.
ConvexHull6 build_convex_hull(std::span<const Eigen::Vector3d> points, HullBuild build = HullBuild::kFastest);
// The same into `hull`, which may hold an earlier hull (its planes past plane_count are left as
// they were, and nothing reads them): for a loop over frames, which would otherwise zero and copy
// 650 bytes a frame.
void build_convex_hull_into(std::span<const Eigen::Vector3d> points, ConvexHull6& hull,
                            HullBuild build = HullBuild::kFastest);

inline bool hull_contains(const ConvexHull6& hull, double qx, double qy, double qz) {
  if (hull.degenerate) return false;
  for (int i = 0; i < hull.plane_count; ++i) {
    const HullPlane& p = hull.planes[static_cast<size_t>(i)];
    if (p.nx * qx + p.ny * qy + p.nz * qz - p.d > ConvexHull6::kTolerance_mm) return false;
  }
  return true;
}

}  // namespace lmc
