#pragma once
// The rig's device messages (connections, slot changes, layout restarts, warnings), newest at
// the bottom, kept scrolled to it unless the operator scrolled up.
#include <memory>

#include "ui/model/devices/devices_state.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class DeviceLogPanel : public Panel {
 public:
  explicit DeviceLogPanel(std::shared_ptr<const DevicesState> state) : Panel("device_log"), state_(std::move(state)) {}
  void draw();

 private:
  std::shared_ptr<const DevicesState> state_;
};

}  // namespace lmc::ui
