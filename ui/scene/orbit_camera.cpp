#include "ui/scene/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/angles.h"

namespace lmc::ui {
namespace {
constexpr double kMinDistance = 20.0;
constexpr double kMaxDistance = 20000.0;
constexpr double kMaxPitch = 89.5;  // straight down would make "up" degenerate
}  // namespace

OrbitCamera::OrbitCamera() : target_(0.0, 80.0, 80.0) {}

void OrbitCamera::set(const Eigen::Vector3d& target, double yaw_deg, double pitch_deg, double distance_mm) {
  target_ = target;
  yaw_deg_ = yaw_deg;
  pitch_deg_ = std::clamp(pitch_deg, -kMaxPitch, kMaxPitch);
  distance_mm_ = std::clamp(distance_mm, kMinDistance, kMaxDistance);
}

Eigen::Vector3d OrbitCamera::eye() const {
  const double cp = std::cos(pitch_deg_ * kRadPerDeg), sp = std::sin(pitch_deg_ * kRadPerDeg);
  const double cy = std::cos(yaw_deg_ * kRadPerDeg), sy = std::sin(yaw_deg_ * kRadPerDeg);
  return target_ + distance_mm_ * Eigen::Vector3d(cp * sy, sp, cp * cy);
}

Eigen::Vector3d OrbitCamera::forward() const {
  return (target_ - eye()).normalized();
}

Eigen::Vector3d OrbitCamera::right() const {
  // Horizontal by construction: perpendicular to the yaw direction.
  const double cy = std::cos(yaw_deg_ * kRadPerDeg), sy = std::sin(yaw_deg_ * kRadPerDeg);
  return Eigen::Vector3d(cy, 0.0, -sy);
}

Eigen::Vector3d OrbitCamera::up() const {
  return right().cross(forward()).normalized();
}

Eigen::Matrix4d OrbitCamera::view() const {
  const Eigen::Vector3d f = forward(), r = right(), u = up(), e = eye();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = r.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -r.dot(e);
  m(1, 3) = -u.dot(e);
  m(2, 3) = f.dot(e);
  return m;
}

Eigen::Matrix4d OrbitCamera::projection(double aspect) const {
  // Near/far follow the distance so the depth buffer keeps its precision at every zoom.
  const double n = std::max(1.0, distance_mm_ * 0.02);
  const double f = distance_mm_ * 6.0 + 3000.0;
  const double t = 1.0 / std::tan(fov_y_deg_ * kRadPerDeg * 0.5);
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = t / std::max(aspect, 1e-6);
  p(1, 1) = t;
  p(2, 2) = (f + n) / (n - f);
  p(2, 3) = 2.0 * f * n / (n - f);
  p(3, 2) = -1.0;
  return p;
}

Ray OrbitCamera::ray_through_pixel(double px, double py, double w, double h) const {
  const double aspect = w / std::max(h, 1.0);
  const double t = std::tan(fov_y_deg_ * kRadPerDeg * 0.5);
  const double ndc_x = (2.0 * px / std::max(w, 1.0)) - 1.0;
  const double ndc_y = 1.0 - (2.0 * py / std::max(h, 1.0));
  Ray r;
  r.origin = eye();
  r.direction = (forward() + right() * (ndc_x * t * aspect) + up() * (ndc_y * t)).normalized();
  return r;
}

std::optional<Eigen::Vector2d> OrbitCamera::project(const Eigen::Vector3d& world, double w, double h) const {
  const Eigen::Vector3d d = world - eye();
  const double z = d.dot(forward());
  if (z <= 1e-6) return std::nullopt;
  const double t = std::tan(fov_y_deg_ * kRadPerDeg * 0.5);
  const double aspect = w / std::max(h, 1.0);
  const double ndc_x = d.dot(right()) / (z * t * aspect);
  const double ndc_y = d.dot(up()) / (z * t);
  return Eigen::Vector2d((ndc_x + 1.0) * 0.5 * w, (1.0 - ndc_y) * 0.5 * h);
}

void OrbitCamera::orbit(double dx_px, double dy_px) {
  yaw_deg_ = std::remainder(yaw_deg_ - dx_px * 0.35, 360.0);
  pitch_deg_ = std::clamp(pitch_deg_ + dy_px * 0.35, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(double dx_px, double dy_px, double viewport_h) {
  // World size of one pixel at the target's depth.
  const double mm_per_px = 2.0 * distance_mm_ * std::tan(fov_y_deg_ * kRadPerDeg * 0.5) / std::max(viewport_h, 1.0);
  target_ += (-dx_px * right() + dy_px * up()) * mm_per_px;
}

void OrbitCamera::zoom_towards(double px, double py, double w, double h, double steps) {
  const double factor = std::pow(0.85, steps);
  const double new_distance = std::clamp(distance_mm_ * factor, kMinDistance, kMaxDistance);
  const double f = new_distance / distance_mm_;
  // The point under the cursor on the plane through the target facing the camera.
  const Ray ray = ray_through_pixel(px, py, w, h);
  const auto t = intersect_plane(ray, target_, forward());
  const Eigen::Vector3d p = t ? ray.at(*t) : target_;
  // Scale the camera about p: eye' = p + (eye − p)·f and target' = p + (target − p)·f keep the
  // orientation, so p projects to the same pixel.
  target_ = p + (target_ - p) * f;
  distance_mm_ = new_distance;
}

void OrbitCamera::frame_bounds(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double aspect) {
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * (hi - lo).norm(), 10.0);
  const double half_v = fov_y_deg_ * kRadPerDeg * 0.5;
  const double half_h = std::atan(std::tan(half_v) * std::max(aspect, 1e-3));
  const double half = std::min(half_v, half_h);
  target_ = centre;
  distance_mm_ = std::clamp(radius / std::sin(half) * 1.05, kMinDistance, kMaxDistance);
}

void OrbitCamera::set_named_view(NamedView view) {
  switch (view) {
    case NamedView::kTop:
      yaw_deg_ = 0.0;
      pitch_deg_ = kMaxPitch;
      break;
    case NamedView::kFront:
      yaw_deg_ = 0.0;
      pitch_deg_ = 8.0;
      break;
    case NamedView::kSide:
      yaw_deg_ = 90.0;
      pitch_deg_ = 8.0;
      break;
    case NamedView::kPerspective:
      yaw_deg_ = 20.0;
      pitch_deg_ = 50.0;
      break;
  }
}

}  // namespace lmc::ui
