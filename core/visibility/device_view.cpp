#include "core/visibility/device_view.h"

namespace lmc {

DeviceView DeviceView::from_pose(const DevicePose& pose, const Eigen::Vector3d& offset_mm) {
  const Eigen::Matrix3d r = pose.rotation();
  const Eigen::Vector3d o = pose.translation() + offset_mm;
  DeviceView v;
  v.ox = o.x();
  v.oy = o.y();
  v.oz = o.z();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) v.rt[3 * i + j] = r(j, i);  // Rᵀ
  }
  const Eigen::Vector3d f = r * Eigen::Vector3d(0, 0, -1);
  v.fx = f.x();
  v.fy = f.y();
  v.fz = f.z();
  return v;
}

}  // namespace lmc
