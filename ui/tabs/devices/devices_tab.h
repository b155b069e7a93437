#pragma once
// The Devices tab (devices_tab.cpp says what it shows): the composition root of its state and
// panels.
#include <memory>

#include "ui/model/devices/devices_state.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/devices/device_log_panel.h"
#include "ui/tabs/devices/device_table_panel.h"
#include "ui/tabs/devices/devices_calibrate_panel.h"
#include "ui/tabs/devices/devices_toolbar_panel.h"
#include "ui/tabs/devices/live_hands_panel.h"
#include "ui/tabs/devices/test_recording_panel.h"
#include "ui/tabs/tab.h"

namespace lmc::ui {

// `context` (the workbench's one layout and live rig) must outlive the tab.
std::unique_ptr<Tab> make_devices_tab(StatusSink& status, WorkbenchContext& context);

class DevicesTab final : public Tab {
 public:
  DevicesTab(StatusSink& status, WorkbenchContext& context);

  void update(bool shown) override;
  void draw() override;

  // Its actions (start a backend, record a calibration, report a line) are the state's.
  DevicesState& state() { return *state_; }

 private:
  void handle_shortcuts();

  std::shared_ptr<DevicesState> state_;  // the panels share it
  DevicesToolbarPanel toolbar_;
  DeviceTablePanel table_;
  TestRecordingPanel recording_;
  LiveHandsPanel live_hands_;
  DevicesCalibratePanel calibrate_;
  DeviceLogPanel log_;
};

}  // namespace lmc::ui
