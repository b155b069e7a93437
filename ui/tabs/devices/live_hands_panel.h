#pragma once
// The Devices tab's 3D view: every controller where the layout puts it and each one's hand
// realigned into the world frame in its colour, the fused hand thick, the fusion's latency above;
// while a calibration result waits, the ghost controllers where the calibration puts them.
#include <memory>

#include "ui/model/devices/devices_state.h"
#include "ui/scene/orbit_camera.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class LiveHandsPanel : public Panel {
 public:
  explicit LiveHandsPanel(std::shared_ptr<const DevicesState> state) : Panel("live_view"), state_(std::move(state)) {}
  void draw();
  const OrbitCamera& camera() const { return camera_; }

 private:
  std::shared_ptr<const DevicesState> state_;
  OrbitCamera camera_;  // starts on the Layout tab's default view, which shows every controller
};

}  // namespace lmc::ui
