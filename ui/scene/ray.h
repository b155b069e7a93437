#pragma once
// Rays and the small intersection tests the scene uses for picking and handles. Picking has fewer
// than a hundred candidates (≤ 8 boxes, 30 joints, bones), so plain CPU tests are enough and run
// headless in tests (docs/architecture.md).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>

namespace lmc::ui {

struct Ray {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit length
  Eigen::Vector3d at(double t) const { return origin + t * direction; }
};

// Distance along the ray to the plane {p : n·(p − point) = 0}; nullopt when the ray is (nearly)
// parallel to it or the hit is behind the origin. care: degenerate rays are skipped, never divided by.
std::optional<double> intersect_plane(const Ray& ray, const Eigen::Vector3d& point, const Eigen::Vector3d& normal);

// Ray against an oriented box: `to_world` maps box coordinates to world, the box spans
// [-half, +half] around `centre_local` in box coordinates. Returns the entry distance (or 0 when
// the origin is inside).
std::optional<double> intersect_oriented_box(const Ray& ray, const Eigen::Isometry3d& to_world,
                                             const Eigen::Vector3d& centre_local, const Eigen::Vector3d& half);

std::optional<double> intersect_sphere(const Ray& ray, const Eigen::Vector3d& centre, double radius);

// Ray against a capsule (segment a–b with radius r): the closest approach of ray and segment.
std::optional<double> intersect_capsule(const Ray& ray, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        double radius);

}  // namespace lmc::ui
