#include "devices/tracking_mode.h"

namespace lmc::devices {

const char* tracking_mode_name(TrackingMode mode) {
  switch (mode) {
    case TrackingMode::kDesktop:
      return "desktop";
    case TrackingMode::kScreenTop:
      return "screen-top";
    case TrackingMode::kHeadMounted:
      return "head-mounted";
    case TrackingMode::kUnknown:
      break;
  }
  return "unknown";
}

TrackingMode tracking_mode_for_pose(const DevicePose& pose) {
  // World y is up; the controller's own y axis is its viewing axis (DevicePose::up).
  return pose.up().y() < 0.0 ? TrackingMode::kScreenTop : TrackingMode::kDesktop;
}

TrackingMode tracking_mode_for_serial(const Layout& layout, const std::string& serial) {
  const int index = layout.find_serial(serial);
  if (index < 0) return TrackingMode::kDesktop;
  return tracking_mode_for_pose(layout.devices[static_cast<size_t>(index)].pose);
}

}  // namespace lmc::devices
