#include "core/geometry/palm_hull.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace lmc {
namespace {

std::vector<Eigen::Vector3d> unit_cube_corners_subset() {
  return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}};
}

TEST(PalmHull, TetrahedronContainsItsCentroidNotOutside) {
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const ConvexHull6 hull = build_convex_hull(pts);
  EXPECT_FALSE(hull.flat);
  EXPECT_EQ(hull.plane_count, 4);
  EXPECT_TRUE(hull_contains(hull, 0.2, 0.2, 0.2));
  EXPECT_FALSE(hull_contains(hull, 0.5, 0.5, 0.5));  // beyond the slanted face x+y+z = 1
  EXPECT_TRUE(hull_contains(hull, 0.0, 0.0, 0.0));   // a vertex counts as inside (feasible LP)
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
}  // namespace lmc
