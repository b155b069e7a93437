#pragma once
// What the visibility tests need to know about one device: its origin o in world coordinates,
// the world→device rotation Rᵀ (for the pyramid test in the device frame) and its forward
// direction f = R·(0, 0, −1) (docs/algorithms/visibility.md). The origin is the full device→world
// transform of the device-frame origin, i.e. pose translation plus calibration offset (docs/algorithms/frames.md).
#include "core/layout/layout.h"

namespace lmc {

struct DeviceView {
  double ox = 0, oy = 0, oz = 0;
  // Row-major Rᵀ: device-frame coordinate i of world vector v is rt[3i]·v.x + rt[3i+1]·v.y + rt[3i+2]·v.z.
  double rt[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  double fx = 0, fy = 0, fz = -1;

  static DeviceView from_pose(const DevicePose& pose, const Eigen::Vector3d& offset_mm = Eigen::Vector3d::Zero());
  static DeviceView from_device(const LayoutDevice& device) { return from_pose(device.pose, device.offset_mm); }
  // The device at its own origin (recorded data in device coordinates).
  static DeviceView identity() { return {}; }
};

}  // namespace lmc
