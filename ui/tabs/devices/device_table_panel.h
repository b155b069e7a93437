#pragma once
// Every controller the rig sees, one row each: its colour, serial, slot (assigned by dropdown),
// backend, model, tracking mode, status, rate, hand present, latest frame age, frames and drops;
// under the table, each controller the layout leaves blind to the hand, named with why.
#include <memory>
#include <string>
#include <vector>

#include "ui/model/devices/devices_state.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class DeviceTablePanel : public Panel {
 public:
  explicit DeviceTablePanel(std::shared_ptr<DevicesState> state) : Panel("##device_table"), state_(std::move(state)) {}
  void draw();

 private:
  void draw_row(const DeviceRow& row, const std::vector<std::string>& slots);
  std::shared_ptr<DevicesState> state_;
};

}  // namespace lmc::ui
