#include "core/geometry/palm_hull.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace lmc {
namespace {

// Slow, independent check: q is inside iff it lies in one of the tetrahedra (or, for coplanar
// points, triangles) spanned by the points (Carathéodory). Solved by Cramer's rule rather than an
// Eigen decomposition, whose templates cost 15 s of compile time under the sanitizers.
double det3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return a.dot(b.cross(c));
}

bool hull_contains_bruteforce(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& q, double tolerance) {
  const size_t n = points.size();
  // Tetrahedra: q = p0 + λ1·e1 + λ2·e2 + λ3·e3 with λ ≥ 0 and Σλ ≤ 1.
  for (size_t a = 0; a < n; ++a) {
    for (size_t b = a + 1; b < n; ++b) {
      for (size_t c = b + 1; c < n; ++c) {
        for (size_t d = c + 1; d < n; ++d) {
          const Eigen::Vector3d e1 = points[b] - points[a], e2 = points[c] - points[a], e3 = points[d] - points[a];
          const double det = det3(e1, e2, e3);
          if (std::abs(det) < 1e-12) continue;
          const Eigen::Vector3d r = q - points[a];
          const Eigen::Vector3d l(det3(r, e2, e3) / det, det3(e1, r, e3) / det, det3(e1, e2, r) / det);
          if (l.minCoeff() >= -tolerance && l.sum() <= 1.0 + tolerance) return true;
        }
      }
    }
  }
  // Triangles (coplanar point sets and points on a flat hull): q = p0 + s·e1 + t·e2 in the
  // triangle's plane; s and t from the 2×2 normal equations, exact once q is in the plane.
  for (size_t a = 0; a < n; ++a) {
    for (size_t b = a + 1; b < n; ++b) {
      for (size_t c = b + 1; c < n; ++c) {
        const Eigen::Vector3d e1 = points[b] - points[a], e2 = points[c] - points[a];
        const Eigen::Vector3d nrm = e1.cross(e2);
        if (nrm.norm() < 1e-12) continue;
        const Eigen::Vector3d r = q - points[a];
        if (std::abs(r.dot(nrm.normalized())) > 1e-6) continue;
        const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
        const double r1 = e1.dot(r), r2 = e2.dot(r);
        const double g = g11 * g22 - g12 * g12;  // = |e1 × e2|² > 0
        const double s = (r1 * g22 - r2 * g12) / g, t = (r2 * g11 - r1 * g12) / g;
        if (s >= -tolerance && t >= -tolerance && s + t <= 1.0 + tolerance) return true;
      }
    }
  }
  return false;
}

std::vector<Eigen::Vector3d> unit_cube_corners_subset() {
  return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}};
}

TEST(PalmHull, TetrahedronContainsItsCentroidNotOutside) {
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const ConvexHull6 hull = build_convex_hull(pts);
  EXPECT_FALSE(hull.flat);
  EXPECT_EQ(hull.plane_count, 4);
  EXPECT_TRUE(hull_contains(hull, 0.2, 0.2, 0.2));
  EXPECT_FALSE(hull_contains(hull, 0.5, 0.5, 0.5));             // beyond the slanted face x+y+z = 1
  EXPECT_TRUE(hull_contains(hull, 0.0, 0.0, 0.0));              // a vertex counts as inside (feasible LP)
  EXPECT_TRUE(hull_contains(hull, 1.0 / 3, 1.0 / 3, 1.0 / 3));  // on a face
  EXPECT_FALSE(hull_contains(hull, -0.001, 0.2, 0.2));
}

TEST(PalmHull, CoplanarPointsGiveThePolygonOnly) {
  // A flat hexagon in the plane z = 5.
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 6; ++i) {
    const double a = i * 3.14159265358979 / 3.0;
    pts.emplace_back(10 * std::cos(a), 10 * std::sin(a), 5.0);
  }
  const ConvexHull6 hull = build_convex_hull(pts);
  EXPECT_TRUE(hull.flat);
  EXPECT_TRUE(hull_contains(hull, 0, 0, 5));
  EXPECT_TRUE(hull_contains(hull, 8.6, 0, 5));
  EXPECT_FALSE(hull_contains(hull, 10.5, 0, 5));
  EXPECT_FALSE(hull_contains(hull, 0, 0, 5.5));  // off the plane
}

TEST(PalmHull, CollinearPointsAreDegenerate) {
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  EXPECT_TRUE(build_convex_hull(pts).degenerate);
}

// The facet test must agree with an independent check (q in some tetrahedron of the points,
// Carathéodory) on random palm-like point sets and random queries away from the boundary.
TEST(PalmHull, AgreesWithBruteForceTetrahedraOnRandomCases) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int inside = 0, outside = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Eigen::Vector3d> pts;
    // Thin, palm-like sets: wide in x/z, thin in y (thickness varies from 0.5 to 20 mm).
    const double thickness = 0.5 + 20.0 * (0.5 + 0.5 * u(rng));
    for (int i = 0; i < 6; ++i) pts.emplace_back(50 * u(rng), thickness * u(rng), 50 * u(rng));
    const ConvexHull6 hull = build_convex_hull(pts);
    for (int q = 0; q < 25; ++q) {
      const Eigen::Vector3d p(40 * u(rng), thickness * u(rng), 40 * u(rng));
      const bool brute = hull_contains_bruteforce(pts, p, 1e-9);
      // Skip the rare queries within 1e-6 of the boundary, where the tolerances may differ.
      const bool brute_loose = hull_contains_bruteforce(pts, p, 1e-6);
      const bool brute_tight = hull_contains_bruteforce(pts, p, -1e-6);
      if (brute_loose != brute_tight) continue;
      EXPECT_EQ(hull_contains(hull, p.x(), p.y(), p.z()), brute) << "trial " << trial << " query " << q;
      (brute ? inside : outside)++;
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

TEST(PalmHull, SixPointHullHasEightTriangularFacetsInGeneralPosition) {
  const auto pts = unit_cube_corners_subset();
  const ConvexHull6 hull = build_convex_hull(pts);
  EXPECT_FALSE(hull.flat);
  EXPECT_GE(hull.plane_count, 6);
  EXPECT_TRUE(hull_contains(hull, 0.3, 0.3, 0.2));
  EXPECT_FALSE(hull_contains(hull, 0.9, 0.9, 0.9));
}

}  // namespace
// The facets of six points four at a time (AVX2) and one by one: the same planes, bit for bit, on
// random palms, flat and nearly flat ones, collinear and repeated points.
TEST(PalmHull, FourAtATimeBuildsTheSamePlanesAsOneByOne) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-300.0, 300.0), unit(-1.0, 1.0);
  const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  int facets = 0;
  for (int trial = 0; trial < 60000; ++trial) {
    std::array<Eigen::Vector3d, 6> pts;
    const Eigen::Vector3d centre(coordinate(rng), coordinate(rng), coordinate(rng));
    const int kind = trial % 4;
    for (auto& p : pts) {
      p = centre + 40.0 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
      if (kind == 1) p.z() = centre.z();                                 // flat
      if (kind == 2) p.z() = centre.z() + 1e-9 * unit(rng);              // nearly flat
      if (kind == 3) p = centre + unit(rng) * Eigen::Vector3d(1, 2, 3);  // collinear
    }
    if (trial % 7 == 0) pts[4] = pts[1];  // a repeated point
    const ConvexHull6 fast = build_convex_hull(pts, HullBuild::kFastest);
    const ConvexHull6 plain = build_convex_hull(pts, HullBuild::kPlain);
    ASSERT_EQ(fast.plane_count, plain.plane_count) << "trial " << trial;
    ASSERT_EQ(fast.flat, plain.flat) << "trial " << trial;
    ASSERT_EQ(fast.degenerate, plain.degenerate) << "trial " << trial;
    for (int i = 0; i < fast.plane_count; ++i) {
      const HullPlane& a = fast.planes[static_cast<size_t>(i)];
      const HullPlane& b = plain.planes[static_cast<size_t>(i)];
      ASSERT_TRUE(bits(a.nx) == bits(b.nx) && bits(a.ny) == bits(b.ny) && bits(a.nz) == bits(b.nz) &&
                  bits(a.d) == bits(b.d))
          << "trial " << trial << " plane " << i;
    }
    facets += fast.flat || fast.degenerate ? 0 : fast.plane_count;
  }
  EXPECT_GT(facets, 60000 / 4 * 4) << "the random palms have real facets to compare";
}

}  // namespace lmc
