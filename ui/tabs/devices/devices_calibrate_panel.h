#pragma once
// The Devices tab's Calibrate section: record a 5 s still hand on the live rig (or
// pick a recorded trial), calibrate with or without Vicon, read the residuals per controller, then
// Apply (one undo step in the layout document, Ctrl+Z here or in the Layout tab takes it back),
// Save the calibrated layout, or Discard. All logic is in ui/model/devices/calibration_step.h; this
// class only draws it and forwards the buttons.
#include <vector>

#include "ui/model/devices/calibration_step.h"
#include "ui/model/workbench_context.h"
#include "ui/scene/scene_items.h"
#include "ui/tabs/tab.h"
#include "ui/widgets/file_browser.h"

namespace lmc::ui {

class DevicesCalibratePanel {
 public:
  DevicesCalibratePanel(StatusSink& status, WorkbenchContext& context);

  // Once a frame after the rig's poll: moves the step on and reports what it says.
  void update();
  // Draws the section into the current window, using the width available.
  void draw();
  // Ctrl+Z while the Devices tab is shown: undoes an applied calibration.
  void undo_shortcut();

  CalibrationStep& step() { return step_; }
  const CalibrationStep& step() const { return step_; }
  // The 3D view's controllers while a result is pending (empty otherwise).
  const std::vector<SceneItem>& ghosts() const { return ghosts_; }

 private:
  void draw_start();
  void draw_progress();
  void draw_result();
  void report(const std::string& text, bool is_error);

  StatusSink& status_;
  CurrentLayout& layout_;
  CalibrationStep step_;
  std::vector<SceneItem> ghosts_;
  std::string last_message_;
  char vicon_[512] = "";
  bool anchor_to_layout_ = false;  // as lmc calibrate: off unless asked
  FileBrowser trial_browser_{"Calibrate from a recorded trial", ".txt"};
  FileBrowser save_browser_{"Save calibrated layout", ".json"};
};

}  // namespace lmc::ui
