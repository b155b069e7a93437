#pragma once
// Handles for moving and turning a controller in the 3D scene (docs/architecture.md), as pure maths that
// takes rays and returns poses, so tests drive it without a window.
//
// * Move: press on the controller's box and drag; the box follows the cursor on the horizontal
//   plane through the device origin (x and z change, y stays).
// * Yaw: the horizontal ring around the controller turns it about the vertical axis (ry).
// * Tilt: the vertical ring around the controller's long axis tilts it about that axis (rx).
// Locked parameters disable their handle (a locked x or z only constrains the move).
//
// Each update computes the pose from the pose at drag start plus the total displacement since the
// press (not step by step), so there is no drift and a test can assert an exact pose.
// care: with rz ≠ 0 (never the case in the study's search) "ry" is not exactly about world-vertical.
#include <optional>
#include <vector>

#include "core/layout/layout.h"
#include "ui/scene/device_locks.h"
#include "ui/scene/orbit_camera.h"
#include "ui/scene/ray.h"

namespace lmc::ui {

enum class HandleKind : int { kNone = 0, kMove, kYaw, kTilt };

// Ring sizes in millimetres: outside every catalogue model's case (ui/scene/device_case.h; the
// widest, an LMC2, is 84 mm long) so they are easy to grab.
inline constexpr double kYawRingRadiusMm = 70.0;
inline constexpr double kTiltRingRadiusMm = 48.0;
// Hover tolerance in screen pixels, so handles stay easy to grab at any zoom.
inline constexpr double kHandleTolerancePx = 9.0;

// Points of a handle ring in world coordinates (closed: the first point is not repeated).
std::vector<Eigen::Vector3d> handle_ring_points(HandleKind kind, const LayoutDevice& device, int segments = 48);

struct HandleHit {
  HandleKind kind = HandleKind::kNone;
  double depth_mm = 0;  // distance from the eye, for "front-most wins"
};

// Which handle of `device` a press at pixel (px, py) would grab; kNone when none is in reach.
HandleHit hover_handle(const LayoutDevice& device, const DeviceLocks& locks, const OrbitCamera& camera, double px,
                       double py, double w, double h);

class DragController {
 public:
  // Starts a drag; false (no drag) when the handle is locked or the ray misses its constraint.
  bool begin(HandleKind kind, const LayoutDevice& device, const DeviceLocks& locks, const Ray& ray);
  // The pose for the current ray; nullopt for a degenerate ray (keep the last pose).
  std::optional<DevicePose> update(const Ray& ray) const;
  void end() { kind_ = HandleKind::kNone; }

  bool active() const { return kind_ != HandleKind::kNone; }
  HandleKind kind() const { return kind_; }
  const DevicePose& start_pose() const { return start_pose_; }

 private:
  std::optional<Eigen::Vector3d> constraint_hit(const Ray& ray) const;
  double angle_of(const Eigen::Vector3d& hit) const;

  HandleKind kind_ = HandleKind::kNone;
  DevicePose start_pose_;
  DeviceLocks locks_;
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();   // device origin in world
  Eigen::Vector3d normal_ = Eigen::Vector3d::UnitY();  // constraint plane normal
  Eigen::Vector3d basis_u_ = Eigen::Vector3d::UnitX(), basis_v_ = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d start_hit_ = Eigen::Vector3d::Zero();
  double start_angle_ = 0;
};

}  // namespace lmc::ui
