#include "core/geometry/palm_hull.h"

namespace lmc {

ConvexHull6 build_convex_hull(std::span<const Eigen::Vector3d> points) {
  ConvexHull6 hull;
  hull.degenerate = points.size() < 3;
  return hull;
}

bool hull_contains_bruteforce(std::span<const Eigen::Vector3d>, const Eigen::Vector3d&, double) {
  return false;
}

}  // namespace lmc
