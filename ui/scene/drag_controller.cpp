#include "ui/scene/drag_controller.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ui/scene/device_case.h"

namespace lmc::ui {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// Below this |cos| between ray and constraint plane the plane is seen edge-on: skip the update.
constexpr double kEdgeOnCos = 0.03;

double wrap_deg(double a) {
  return std::remainder(a, 360.0);
}

struct RingFrame {
  Eigen::Vector3d centre, u, v, normal;
  double radius;
};

// Yaw ring: horizontal, angle measured so that a positive angle is a positive rotation about +y
// (Ry(θ)·x̂ = (cos θ, 0, −sin θ), hence u = x̂, v = −ẑ).
// Tilt ring: in the plane normal to the device's long axis a = R·x̂; Rx(θ)·ŷ = (0, cos θ, sin θ)
// in the frame before rx, so u = Rz·Ry·ŷ and v = Rz·Ry·ẑ make a positive angle a positive rx.
RingFrame ring_frame(HandleKind kind, const LayoutDevice& device) {
  RingFrame f;
  f.centre = device.to_world(Eigen::Vector3d::Zero());
  if (kind == HandleKind::kYaw) {
    f.u = Eigen::Vector3d::UnitX();
    f.v = -Eigen::Vector3d::UnitZ();
    f.normal = Eigen::Vector3d::UnitY();
    f.radius = kYawRingRadiusMm;
  } else {
    DevicePose no_rx = device.pose;
    no_rx.rx_deg = 0;
    const Eigen::Matrix3d r = no_rx.rotation();
    f.u = r * Eigen::Vector3d::UnitY();
    f.v = r * Eigen::Vector3d::UnitZ();
    f.normal = r * Eigen::Vector3d::UnitX();
    f.radius = kTiltRingRadiusMm;
  }
  return f;
}

double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                              double* s_out) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  double s = len2 > 1e-12 ? (p - a).dot(ab) / len2 : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  *s_out = s;
  return (p - (a + s * ab)).norm();
}

}  // namespace

std::vector<Eigen::Vector3d> handle_ring_points(HandleKind kind, const LayoutDevice& device, int segments) {
  std::vector<Eigen::Vector3d> pts;
  if (kind != HandleKind::kYaw && kind != HandleKind::kTilt) return pts;
  const RingFrame f = ring_frame(kind, device);
  pts.reserve(static_cast<size_t>(segments));
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * std::numbers::pi * i / segments;
    pts.push_back(f.centre + f.radius * (std::cos(a) * f.u + std::sin(a) * f.v));
  }
  return pts;
}

HandleHit hover_handle(const LayoutDevice& device, const DeviceLocks& locks, const OrbitCamera& camera, double px,
                       double py, double w, double h) {
  HandleHit best;
  double best_depth = std::numeric_limits<double>::infinity();
  const Eigen::Vector2d mouse(px, py);
  const Eigen::Vector3d eye = camera.eye();
  for (HandleKind kind : {HandleKind::kYaw, HandleKind::kTilt}) {
    const bool locked = kind == HandleKind::kYaw ? locks.locked[4] : locks.locked[3];
    if (locked) continue;
    // A ring seen (nearly) edge-on collapses to a line across the box: it could not be dragged
    // reliably anyway, so it does not compete for the press.
    const RingFrame frame = ring_frame(kind, device);
    if (std::abs((frame.centre - eye).normalized().dot(frame.normal)) < 0.2) continue;
    const auto pts = handle_ring_points(kind, device);
    for (size_t i = 0; i < pts.size(); ++i) {
      const auto& a3 = pts[i];
      const auto& b3 = pts[(i + 1) % pts.size()];
      const auto a = camera.project(a3, w, h);
      const auto b = camera.project(b3, w, h);
      if (!a || !b) continue;
      double s = 0;
      if (point_segment_distance(mouse, *a, *b, &s) > kHandleTolerancePx) continue;
      const double depth = (a3 + s * (b3 - a3) - eye).norm();
      if (depth < best_depth) {
        best_depth = depth;
        best = {kind, depth};
      }
    }
  }
  const bool move_locked = locks.locked[0] && locks.locked[2];
  if (!move_locked) {
    const Ray ray = camera.ray_through_pixel(px, py, w, h);
    Eigen::Isometry3d to_world = device.pose.device_to_world();
    to_world.translation() += device.offset_mm;
    const DeviceCaseBox case_box = device_case_box(device);
    if (const auto t = intersect_oriented_box(ray, to_world, case_box.centre_mm, case_box.half_mm)) {
      if (*t < best_depth) best = {HandleKind::kMove, *t};
    }
  }
  return best;
}

bool DragController::begin(HandleKind kind, const LayoutDevice& device, const DeviceLocks& locks, const Ray& ray) {
  kind_ = HandleKind::kNone;
  if (kind == HandleKind::kNone) return false;
  if (kind == HandleKind::kMove && locks.locked[0] && locks.locked[2]) return false;
  if (kind == HandleKind::kYaw && locks.locked[4]) return false;
  if (kind == HandleKind::kTilt && locks.locked[3]) return false;
  start_pose_ = device.pose;
  locks_ = locks;
  if (kind == HandleKind::kMove) {
    centre_ = device.to_world(Eigen::Vector3d::Zero());
    normal_ = Eigen::Vector3d::UnitY();
  } else {
    const RingFrame f = ring_frame(kind, device);
    centre_ = f.centre;
    normal_ = f.normal;
    basis_u_ = f.u;
    basis_v_ = f.v;
  }
  kind_ = kind;
  const auto hit = constraint_hit(ray);
  if (!hit) {
    kind_ = HandleKind::kNone;
    return false;
  }
  start_hit_ = *hit;
  start_angle_ = angle_of(*hit);
  return true;
}

std::optional<Eigen::Vector3d> DragController::constraint_hit(const Ray& ray) const {
  if (std::abs(ray.direction.dot(normal_)) < kEdgeOnCos) return std::nullopt;
  const auto t = intersect_plane(ray, centre_, normal_);
  if (!t) return std::nullopt;
  return ray.at(*t);
}

double DragController::angle_of(const Eigen::Vector3d& hit) const {
  const Eigen::Vector3d d = hit - centre_;
  return std::atan2(d.dot(basis_v_), d.dot(basis_u_));
}

std::optional<DevicePose> DragController::update(const Ray& ray) const {
  if (!active()) return std::nullopt;
  const auto hit = constraint_hit(ray);
  if (!hit) return std::nullopt;
  DevicePose pose = start_pose_;
  if (kind_ == HandleKind::kMove) {
    const Eigen::Vector3d delta = *hit - start_hit_;
    if (!locks_.locked[0]) pose.x_mm = start_pose_.x_mm + delta.x();
    if (!locks_.locked[2]) pose.z_mm = start_pose_.z_mm + delta.z();
    return pose;
  }
  // Too close to the ring's centre the angle is meaningless.
  if ((*hit - centre_).norm() < 3.0) return std::nullopt;
  const double delta_deg = (angle_of(*hit) - start_angle_) * kRadToDeg;
  if (kind_ == HandleKind::kYaw) {
    pose.ry_deg = wrap_deg(start_pose_.ry_deg + delta_deg);
  } else {
    pose.rx_deg = wrap_deg(start_pose_.rx_deg + delta_deg);
  }
  return pose;
}

}  // namespace lmc::ui
