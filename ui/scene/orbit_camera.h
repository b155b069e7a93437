#pragma once
// The scene camera as a pure object (docs/architecture.md): orbit, pan and zoom take deltas, not mouse
// gestures, so the scene panel maps gestures and tests check the maths.
//
// World frame (docs/algorithms/frames.md): y up, table top y = 0, z towards the subject. The
// camera orbits a target point; yaw 0 looks from the subject's side (+z) towards −z, pitch is the
// elevation above the table plane.
#include <Eigen/Core>
#include <optional>

#include "ui/scene/ray.h"

namespace lmc::ui {

enum class NamedView : int { kPerspective = 0, kTop, kFront, kSide };

class OrbitCamera {
 public:
  OrbitCamera();

  // ---- state --------------------------------------------------------------------------------
  Eigen::Vector3d target() const { return target_; }
  double yaw_deg() const { return yaw_deg_; }
  double pitch_deg() const { return pitch_deg_; }
  double distance_mm() const { return distance_mm_; }
  double fov_y_deg() const { return fov_y_deg_; }
  Eigen::Vector3d eye() const;
  Eigen::Vector3d forward() const;  // unit, eye → target
  Eigen::Vector3d right() const;    // unit, screen x
  Eigen::Vector3d up() const;       // unit, screen y

  void set(const Eigen::Vector3d& target, double yaw_deg, double pitch_deg, double distance_mm);

  // ---- matrices (column vectors, OpenGL clip conventions) ---------------------------------------
  Eigen::Matrix4d view() const;
  Eigen::Matrix4d projection(double aspect) const;

  // ---- screen <-> world (pixels from the top-left of a w × h viewport) ----------------------
  Ray ray_through_pixel(double px, double py, double w, double h) const;
  // Pixel position of a world point; nullopt when it is behind the camera.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& world, double w, double h) const;

  // ---- gestures as deltas ---------------------------------------------------------------------
  void orbit(double dx_px, double dy_px);                   // 0.35° per pixel
  void pan(double dx_px, double dy_px, double viewport_h);  // the target moves with the cursor
  // Zooms by `steps` wheel notches (positive = closer) keeping the point under (px, py) fixed on
  // screen: the whole camera is scaled about that point, which leaves its projection unchanged.
  void zoom_towards(double px, double py, double w, double h, double steps);
  // Centres and fits an axis-aligned box (with a margin) without changing the view direction.
  void frame_bounds(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double aspect);
  void set_named_view(NamedView view);

 private:
  Eigen::Vector3d target_;
  double yaw_deg_ = 20.0;
  double pitch_deg_ = 50.0;
  double distance_mm_ = 900.0;
  double fov_y_deg_ = 40.0;
};

}  // namespace lmc::ui
