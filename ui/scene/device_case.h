#pragma once
// A controller's case as the scene draws and picks it: a box in device coordinates sized by the
// device's own model (LayoutDevice::footprint_mm for width and depth, the catalogue's height and
// where the device origin sits on the case, core/layout/sensor_catalogue.h), so an LMC2 is drawn
// 84 × 20 mm and an LMC 80 × 30 mm. The origin is the top centre for every model in the catalogue,
// so the box hangs below it.
#include <Eigen/Core>

#include "core/layout/layout.h"

namespace lmc::ui {

struct DeviceCaseBox {
  Eigen::Vector3d centre_mm = Eigen::Vector3d::Zero();  // device coordinates
  Eigen::Vector3d half_mm = Eigen::Vector3d::Zero();    // half width (x), height (y), depth (z)
  double top_y_mm() const { return centre_mm.y() + half_mm.y(); }
};

// The case of `device`; a model missing from the catalogue keeps its footprint and gets the
// original controller's height with the origin on top.
DeviceCaseBox device_case_box(const LayoutDevice& device);

}  // namespace lmc::ui
