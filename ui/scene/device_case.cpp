#include "ui/scene/device_case.h"

#include "core/io/sensor_catalogue_json.h"

namespace lmc::ui {

DeviceCaseBox device_case_box(const LayoutDevice& device) {
  double height_mm = 11.3;
  Eigen::Vector3d origin_in_case_mm(0, height_mm, 0);
  if (const SensorSpec* spec = sensor_catalogue().find(device.model)) {
    height_mm = spec->footprint_mm.z();
    origin_in_case_mm = spec->origin_in_case_mm;
  }
  DeviceCaseBox box;
  box.half_mm = Eigen::Vector3d(device.footprint_mm.x() * 0.5, height_mm * 0.5, device.footprint_mm.y() * 0.5);
  // The case's bottom-face centre is at −origin_in_case in device coordinates.
  box.centre_mm = Eigen::Vector3d(0, height_mm * 0.5, 0) - origin_in_case_mm;
  return box;
}

}  // namespace lmc::ui
