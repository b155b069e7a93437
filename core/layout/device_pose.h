#pragma once
// A device pose places a controller on the table (docs/algorithms/frames.md):
// p_world = R·p_device + t with R = Rz(rz)·Ry(ry)·Rx(rx) (x applied first), t = (x, y, z).
// Millimetres and degrees, as in the study's tables.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lmc {

struct DevicePose {
  double x_mm = 0, y_mm = 0, z_mm = 0;
  double rx_deg = 0, ry_deg = 0, rz_deg = 0;

  // Parameter k in the order {x, y, z, rx, ry, rz}; the optimiser and inspector index this way.
  double get(int k) const;
  void set(int k, double value);

  Eigen::Matrix3d rotation() const;
  // Sets rx, ry, rz so that rotation() == r (r must be a rotation). At ry = ±90° (gimbal lock)
  // rz is set to 0 and rx takes the whole turn about the remaining axis.
  void set_rotation(const Eigen::Matrix3d& r);
  Eigen::Vector3d translation() const { return {x_mm, y_mm, z_mm}; }
  Eigen::Isometry3d device_to_world() const;

  Eigen::Vector3d to_world(const Eigen::Vector3d& p_device) const { return rotation() * p_device + translation(); }
  // The direction the controller looks at "forward" in world terms: R·(0, 0, −1), away from
  // the user (docs/algorithms/visibility.md).
  Eigen::Vector3d forward() const;
  Eigen::Vector3d up() const;  // R·(0, 1, 0): the viewing axis

  bool operator==(const DevicePose&) const = default;
};

inline constexpr int kNumPoseParams = 6;
// "x", "y", "z", "rx", "ry", "rz"
const char* pose_param_name(int k);
int pose_param_from_name(const char* name);  // −1 when unknown

}  // namespace lmc
