#pragma once
// The Devices tab's Calibrate section: record a 5 s still hand on the live rig (or
// pick a recorded trial), calibrate with or without Vicon, read the residuals per controller, then
// Apply (one undo step in the layout document, Ctrl+Z here or in the Layout tab takes it back),
// Save the calibrated layout, or Discard. The step is the tab's state's (DevicesState::calibration,
// ui/model/devices/calibration_step.h); this class only draws it and forwards the buttons.
#include <memory>

#include "ui/model/devices/devices_state.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class DevicesCalibratePanel : public Panel {
 public:
  explicit DevicesCalibratePanel(std::shared_ptr<DevicesState> state) : Panel("calibrate"), state_(std::move(state)) {}

  // Draws the section into the current window, using the width available.
  void draw();

 private:
  void draw_start();
  void draw_progress();
  void draw_result();

  std::shared_ptr<DevicesState> state_;
  char vicon_[512] = "";
  bool anchor_to_layout_ = false;  // as lmc calibrate: off unless asked
  FileBrowser trial_browser_{"Calibrate from a recorded trial", ".txt"};
  FileBrowser save_browser_{"Save calibrated layout", ".json"};
};

}  // namespace lmc::ui
