#include "core/layout/device_pose.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "core/common/angles.h"

namespace lmc {

namespace {
constexpr const char* kParamNames[kNumPoseParams] = {"x", "y", "z", "rx", "ry", "rz"};
}  // namespace

double DevicePose::get(int k) const {
  switch (k) {
    case 0:
      return x_mm;
    case 1:
      return y_mm;
    case 2:
      return z_mm;
    case 3:
      return rx_deg;
    case 4:
      return ry_deg;
    default:
      return rz_deg;
  }
}

void DevicePose::set(int k, double value) {
  switch (k) {
    case 0:
      x_mm = value;
      break;
    case 1:
      y_mm = value;
      break;
    case 2:
      z_mm = value;
      break;
    case 3:
      rx_deg = value;
      break;
    case 4:
      ry_deg = value;
      break;
    default:
      rz_deg = value;
      break;
  }
}

Eigen::Matrix3d DevicePose::rotation() const {
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  return (AngleAxisd(rz_deg * kRadPerDeg, Vector3d::UnitZ()) * AngleAxisd(ry_deg * kRadPerDeg, Vector3d::UnitY()) *
          AngleAxisd(rx_deg * kRadPerDeg, Vector3d::UnitX()))
      .toRotationMatrix();
}

void DevicePose::set_rotation(const Eigen::Matrix3d& r) {
  // R = Rz(c)·Ry(b)·Rx(a): R(2,0) = −sin b, R(2,1) = cos b·sin a, R(2,2) = cos b·cos a,
  // R(1,0) = sin c·cos b, R(0,0) = cos c·cos b.
  // atan2 rather than asin(−R(2,0)): asin loses half the digits near ±90°.
  const double cb = std::sqrt(r(2, 1) * r(2, 1) + r(2, 2) * r(2, 2));
  const double b = std::atan2(-r(2, 0), cb);
  double a = 0, c = 0;
  if (cb > 1e-9) {
    a = std::atan2(r(2, 1), r(2, 2));
    c = std::atan2(r(1, 0), r(0, 0));
  } else {
    a = std::atan2(-r(1, 2), r(1, 1));  // with c = 0, row 1 of Ry·Rx is (0, cos a, −sin a)
  }
  rx_deg = a / kRadPerDeg;
  ry_deg = b / kRadPerDeg;
  rz_deg = c / kRadPerDeg;
}

Eigen::Isometry3d DevicePose::device_to_world() const {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = rotation();
  t.translation() = translation();
  return t;
}

Eigen::Vector3d DevicePose::forward() const {
  return rotation() * Eigen::Vector3d(0, 0, -1);
}
Eigen::Vector3d DevicePose::up() const {
  return rotation() * Eigen::Vector3d(0, 1, 0);
}

const char* pose_param_name(int k) {
  return (k >= 0 && k < kNumPoseParams) ? kParamNames[k] : "?";
}

int pose_param_from_name(const char* name) {
  for (int k = 0; k < kNumPoseParams; ++k) {
    if (std::strcmp(kParamNames[k], name) == 0) return k;
  }
  return -1;
}

}  // namespace lmc
