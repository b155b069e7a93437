#include "core/geometry/palm_hull.h"

#include <Eigen/Geometry>  // cross products; no decomposition here
#include <algorithm>
#include <array>
#include <cmath>

#include "core/common/cpu_features.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

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

// The candidate facets of six points, (i, j, k) with i < j < k in the order of the loops below.
constexpr int kTriples = 20;
struct TripleIndices {
  std::array<int, kTriples> i{}, j{}, k{};
};
constexpr TripleIndices kSixPointTriples = [] {
  TripleIndices t;
  int n = 0;
  for (int i = 0; i < 6; ++i) {
    for (int j = i + 1; j < 6; ++j) {
      for (int k = j + 1; k < 6; ++k) {
        t.i[static_cast<size_t>(n)] = i;
        t.j[static_cast<size_t>(n)] = j;
        t.k[static_cast<size_t>(n)] = k;
        ++n;
      }
    }
  }
  return t;
}();

// Each candidate facet of six points: its unit normal, whether its points are collinear, and which
// sides of its plane the six points lie on.
struct Candidates {
  std::array<double, kTriples> nx{}, ny{}, nz{};
  std::array<bool, kTriples> collinear{}, positive{}, negative{};
};

#if defined(__x86_64__) && defined(__GNUC__)
// One coordinate of the i-th (j-th, k-th) points of candidates t … t + 3.
[[gnu::target("avx2"), gnu::always_inline]] inline __m256d gather4(const std::array<double, 6>& v,
                                                                   const std::array<int, kTriples>& at, int t) {
  const auto coordinate = [&](int q) { return v[static_cast<size_t>(at[static_cast<size_t>(t + q)])]; };
  return _mm256_set_pd(coordinate(3), coordinate(2), coordinate(1), coordinate(0));
}

// Four candidates at a time. Every value is what the loop in build_convex_hull computes with Eigen
// for one triple: the cross product's components as Eigen writes them, squared norms and dot
// products summed x, y, then z, one square root and one division per component.
[[gnu::target("avx2")]] Candidates six_point_candidates_avx2(std::span<const Eigen::Vector3d> pts, double collinear_len,
                                                             double side_tol) {
  Candidates c;
  std::array<double, 6> px{}, py{}, pz{};
  for (size_t m = 0; m < 6; ++m) {
    px[m] = pts[m].x();
    py[m] = pts[m].y();
    pz[m] = pts[m].z();
  }
  const auto& tri = kSixPointTriples;
  const __m256d tol = _mm256_set1_pd(side_tol), minus_tol = _mm256_set1_pd(-side_tol);
  const __m256d limit = _mm256_set1_pd(collinear_len);
  for (int t = 0; t < kTriples; t += 4) {
    const __m256d ix = gather4(px, tri.i, t), iy = gather4(py, tri.i, t), iz = gather4(pz, tri.i, t);
    const __m256d ax = _mm256_sub_pd(gather4(px, tri.j, t), ix), ay = _mm256_sub_pd(gather4(py, tri.j, t), iy),
                  az = _mm256_sub_pd(gather4(pz, tri.j, t), iz);
    const __m256d bx = _mm256_sub_pd(gather4(px, tri.k, t), ix), by = _mm256_sub_pd(gather4(py, tri.k, t), iy),
                  bz = _mm256_sub_pd(gather4(pz, tri.k, t), iz);
    const __m256d cx = _mm256_sub_pd(_mm256_mul_pd(ay, bz), _mm256_mul_pd(az, by));
    const __m256d cy = _mm256_sub_pd(_mm256_mul_pd(az, bx), _mm256_mul_pd(ax, bz));
    const __m256d cz = _mm256_sub_pd(_mm256_mul_pd(ax, by), _mm256_mul_pd(ay, bx));
    const __m256d len = _mm256_sqrt_pd(
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(cx, cx), _mm256_mul_pd(cy, cy)), _mm256_mul_pd(cz, cz)));
    const __m256d collinear = _mm256_cmp_pd(len, limit, _CMP_LE_OQ);
    const __m256d nx = _mm256_div_pd(cx, len), ny = _mm256_div_pd(cy, len), nz = _mm256_div_pd(cz, len);
    const __m256d d = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(nx, ix), _mm256_mul_pd(ny, iy)), _mm256_mul_pd(nz, iz));
    __m256d positive = _mm256_setzero_pd(), negative = _mm256_setzero_pd();
    for (size_t m = 0; m < 6; ++m) {
      const __m256d dot = _mm256_add_pd(
          _mm256_add_pd(_mm256_mul_pd(nx, _mm256_set1_pd(px[m])), _mm256_mul_pd(ny, _mm256_set1_pd(py[m]))),
          _mm256_mul_pd(nz, _mm256_set1_pd(pz[m])));
      const __m256d side = _mm256_sub_pd(dot, d);
      positive = _mm256_or_pd(positive, _mm256_cmp_pd(side, tol, _CMP_GT_OQ));
      negative = _mm256_or_pd(negative, _mm256_cmp_pd(side, minus_tol, _CMP_LT_OQ));
    }
    _mm256_storeu_pd(c.nx.data() + t, nx);
    _mm256_storeu_pd(c.ny.data() + t, ny);
    _mm256_storeu_pd(c.nz.data() + t, nz);
    const int col = _mm256_movemask_pd(collinear), pos = _mm256_movemask_pd(positive),
              neg = _mm256_movemask_pd(negative);
    for (int q = 0; q < 4; ++q) {
      c.collinear[static_cast<size_t>(t + q)] = ((col >> q) & 1) != 0;
      c.positive[static_cast<size_t>(t + q)] = ((pos >> q) & 1) != 0;
      c.negative[static_cast<size_t>(t + q)] = ((neg >> q) & 1) != 0;
    }
  }
  return c;
}

#endif

// The candidates four at a time where the CPU has AVX2; false (and nothing computed) elsewhere.
bool six_point_candidates(std::span<const Eigen::Vector3d> pts, double collinear_len, double side_tol,
                          Candidates& out) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (cpu_has_avx2()) {
    out = six_point_candidates_avx2(pts, collinear_len, side_tol);
    return true;
  }
#else
  (void)pts;
  (void)collinear_len;
  (void)side_tol;
  (void)out;
#endif
  return false;
}

}  // namespace

ConvexHull6 build_convex_hull(std::span<const Eigen::Vector3d> points, HullBuild build) {
  ConvexHull6 hull;
  build_convex_hull_into(points, hull, build);
  return hull;
}

void build_convex_hull_into(std::span<const Eigen::Vector3d> points, ConvexHull6& hull, HullBuild build) {
  hull.plane_count = 0;
  hull.flat = false;
  hull.degenerate = false;
  const size_t n = std::min(points.size(), static_cast<size_t>(ConvexHull6::kMaxPoints));
  const std::span<const Eigen::Vector3d> pts = points.first(n);
  if (n < 3) {
    hull.degenerate = true;
    return;
  }
  const double extent = extent_of(pts);
  if (!(extent > 0.0) || !std::isfinite(extent)) {
    hull.degenerate = true;
    return;
  }
  // Side tolerance for "all other points are behind this plane": relative to the hull's size.
  const double side_tol = 1e-9 * extent;

  // 3-D case: every triple whose plane has all other points on one side is a facet (coplanar
  // facets with four points appear several times; duplicates are harmless).
  bool any_nondegenerate_triple = false;
  Eigen::Vector3d some_normal = Eigen::Vector3d::Zero();
  // Each candidate facet in order: a collinear triple is skipped; any other keeps its normal (for
  // the flat case below) and is a facet when every point is on one side of its plane.
  const auto take = [&](const Eigen::Vector3d& unit_normal, size_t i, Sides sides) {
    any_nondegenerate_triple = true;
    some_normal = unit_normal;
    if (sides.positive && sides.negative) return;    // a plane through the middle, not a facet
    if (!sides.positive && !sides.negative) return;  // all coplanar: handled below
    add_outward_plane(hull, unit_normal, pts[i], sides);
  };
  const double collinear_len = kDegenerateRel * extent * extent;
  Candidates c;
  if (n == 6 && build == HullBuild::kFastest && six_point_candidates(pts, collinear_len, side_tol, c)) {
    for (size_t t = 0; t < static_cast<size_t>(kTriples); ++t) {
      if (c.collinear[t]) continue;
      take(Eigen::Vector3d(c.nx[t], c.ny[t], c.nz[t]), static_cast<size_t>(kSixPointTriples.i[t]),
           Sides{c.positive[t], c.negative[t]});
    }
  } else {
    for (size_t i = 0; i < n; ++i) {
      for (size_t j = i + 1; j < n; ++j) {
        for (size_t k = j + 1; k < n; ++k) {
          Eigen::Vector3d nrm = (pts[j] - pts[i]).cross(pts[k] - pts[i]);
          const double len = nrm.norm();
          if (len <= collinear_len) continue;  // collinear triple
          nrm /= len;
          take(nrm, i, sides_of(nrm, pts[i], pts, side_tol));
        }
      }
    }
  }
  if (!any_nondegenerate_triple) {
    hull.degenerate = true;  // all points collinear
    return;
  }
  if (hull.plane_count > 0) return;

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
}

}  // namespace lmc
