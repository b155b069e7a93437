#include "core/processing/realign.h"

#include "core/common/error.h"

namespace lmc {

void realign_frame(std::span<Vec3, kNumHandPoints> points, const Eigen::Matrix3d& r, const Eigen::Vector3d& shift) {
  for (int i = 0; i < kNumHandPoints; ++i) {
    Vec3& p = points[static_cast<size_t>(i)];
    if (i == kPalmNormal || i == kPalmDirection) {
      p = r * p;
    } else {
      p = r * p + shift;
    }
  }
}

void realign_track(HandTrack& track, const LayoutDevice& device) {
  const Eigen::Matrix3d r = device.pose.rotation();
  const Eigen::Vector3d shift = device.pose.translation() + device.offset_mm;
  for (int f = 0; f < track.frame_count; ++f) {
    realign_frame(std::span<Vec3, kNumHandPoints>(&track.at(f, 0), kNumHandPoints), r, shift);
  }
}

void realign_to_world(GridTrial& grid, const Layout& layout, const std::string& layout_source) {
  for (auto& dev : grid.devices) {
    if (dev.device_id < 1 || dev.device_id > layout.device_count()) {
      throw Error(ErrorLocation(layout_source, 0, 0, "/devices"),
                  "the recording has device " + std::to_string(dev.device_id) + " but layout '" + layout.name +
                      "' has only " + std::to_string(layout.device_count()) + " device(s)");
    }
    realign_track(dev.track, layout.devices[static_cast<size_t>(dev.device_id - 1)]);
  }
}

}  // namespace lmc
