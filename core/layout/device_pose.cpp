#include "core/layout/device_pose.h"

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
    case 0: return x_mm;
    case 1: return y_mm;
    case 2: return z_mm;
    case 3: return rx_deg;
    case 4: return ry_deg;
    default: return rz_deg;
  }
}

void DevicePose::set(int k, double value) {
  switch (k) {
    case 0: x_mm = value; break;
    case 1: y_mm = value; break;
    case 2: z_mm = value; break;
    case 3: rx_deg = value; break;
    case 4: ry_deg = value; break;
    default: rz_deg = value; break;
  }
}

Eigen::Matrix3d DevicePose::rotation() const {
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  return (AngleAxisd(rz_deg * kRadPerDeg, Vector3d::UnitZ()) *
          AngleAxisd(ry_deg * kRadPerDeg, Vector3d::UnitY()) *
          AngleAxisd(rx_deg * kRadPerDeg, Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d DevicePose::device_to_world() const {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = rotation();
  t.translation() = translation();
  return t;
}

Eigen::Vector3d DevicePose::forward() const { return rotation() * Eigen::Vector3d(0, 0, -1); }
Eigen::Vector3d DevicePose::up() const { return rotation() * Eigen::Vector3d(0, 1, 0); }

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
