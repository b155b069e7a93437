#include "ui/scene/ray.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lmc::ui {

std::optional<double> intersect_plane(const Ray& ray, const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  const double denom = normal.dot(ray.direction);
  if (std::abs(denom) < 1e-9) return std::nullopt;
  const double t = normal.dot(point - ray.origin) / denom;
  if (t < 0) return std::nullopt;
  return t;
}

std::optional<double> intersect_oriented_box(const Ray& ray, const Eigen::Isometry3d& to_world,
                                             const Eigen::Vector3d& centre_local, const Eigen::Vector3d& half) {
  // Slab test in box coordinates (the isometry keeps distances, so t carries over).
  const Eigen::Isometry3d to_local = to_world.inverse();
  const Eigen::Vector3d o = to_local * ray.origin - centre_local;
  const Eigen::Vector3d d = to_local.linear() * ray.direction;
  double t_near = -std::numeric_limits<double>::infinity();
  double t_far = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-12) {
      if (o[a] < -half[a] || o[a] > half[a]) return std::nullopt;
      continue;
    }
    double t1 = (-half[a] - o[a]) / d[a];
    double t2 = (half[a] - o[a]) / d[a];
    if (t1 > t2) std::swap(t1, t2);
    t_near = std::max(t_near, t1);
    t_far = std::min(t_far, t2);
    if (t_near > t_far) return std::nullopt;
  }
  if (t_far < 0) return std::nullopt;
  return std::max(t_near, 0.0);
}

std::optional<double> intersect_sphere(const Ray& ray, const Eigen::Vector3d& centre, double radius) {
  const Eigen::Vector3d oc = ray.origin - centre;
  const double b = oc.dot(ray.direction);
  const double c = oc.squaredNorm() - radius * radius;
  const double disc = b * b - c;
  if (disc < 0) return std::nullopt;
  const double s = std::sqrt(disc);
  double t = -b - s;
  if (t < 0) t = -b + s;
  if (t < 0) return std::nullopt;
  return t;
}

std::optional<double> intersect_capsule(const Ray& ray, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        double radius) {
  // Closest points between the ray (o + t·d) and the segment (a + s·(b − a)), s clamped to [0, 1].
  const Eigen::Vector3d u = b - a;
  const double uu = u.squaredNorm();
  if (uu < 1e-12) return intersect_sphere(ray, a, radius);
  const Eigen::Vector3d w = ray.origin - a;
  const double du = ray.direction.dot(u);
  const double denom = uu - du * du;  // |d|=1
  double s = 0.5;
  if (std::abs(denom) > 1e-12) s = (u.dot(w) - du * ray.direction.dot(w)) / denom;
  s = std::clamp(s, 0.0, 1.0);
  const Eigen::Vector3d p = a + s * u;
  const double t = std::max(0.0, ray.direction.dot(p - ray.origin));
  if ((ray.at(t) - p).norm() > radius) return std::nullopt;
  return t;
}

}  // namespace lmc::ui
