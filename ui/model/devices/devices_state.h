#pragma once
// The Devices tab's state, without ImGui: what the tab owns and its panels read. The live rig's
// view (DevicesViewModel: table rows, hands, the fused hand, the rig's test recording), the
// Calibrate step (CalibrationStep and its job) with the ghost controllers it shows, and the
// actions the panels call, each reporting its outcome in the status line. Panels never reach
// the rig, a device or a file themselves.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "ui/model/current_layout.h"
#include "ui/model/devices/calibration_step.h"
#include "ui/model/devices/devices_view_model.h"
#include "ui/model/devices/live_rig.h"
#include "ui/scene/scene_items.h"

namespace lmc::ui {

class DevicesState {
 public:
  using StatusFn = std::function<void(const std::string&, bool is_error)>;
  // `rig` and `layout`: the workbench context's, which outlive every tab.
  DevicesState(LiveRig& rig, CurrentLayout& layout, StatusFn status = {});
  DevicesState(const DevicesState&) = delete;
  DevicesState& operator=(const DevicesState&) = delete;

  DevicesViewModel& view() { return view_; }
  const DevicesViewModel& view() const { return view_; }
  CalibrationStep& calibration() { return calibration_; }
  const CalibrationStep& calibration() const { return calibration_; }
  // The workbench's layout: what a recorded trial is calibrated against, and the editor an
  // applied calibration goes through (one undo step of the Layout tab's history).
  CurrentLayout& shared_layout() { return layout_; }
  // The 3D view's controllers while a calibration result waits (empty otherwise).
  const std::vector<SceneItem>& ghosts() const { return ghosts_; }

  // Once a frame: polls the rig and the calibration step, and puts in the status line what
  // happened since (a layout restart, a test recording's end, the step's message), whichever
  // tab started it.
  void update();

  // ---- the rig ------------------------------------------------------------------------------
  // True when a usable LeapC library is installed now (devices/leapc/leapc_library.h).
  static bool leapc_available();
  // The first time the tab is drawn: LeapC when Ultraleap's library is installed (the simulated rig
  // takes over if no controller shows up within 3 s), else the simulated rig. Start with leapc
  // looks again, so software installed while the workbench runs is found; its log says which
  // library was loaded from where, and a failed start every place tried.
  void auto_start();
  bool auto_started() const { return auto_started_; }
  // Starts a backend ("sim", "leapc", "replay:FILE"); an error goes to the status line and is
  // returned ("" when started). A start that works replaces an error the line still shows.
  std::string start(const std::string& backend, const devices::SimConfig& sim = {});
  void stop() { view_.stop(); }
  void assign(const std::string& serial, const std::string& slot);
  void save_layout_with_serials(const std::filesystem::path& file);

  // ---- the test recording -------------------------------------------------------------------
  void start_recording(const std::filesystem::path& dir, const std::string& trial, double seconds);
  void stop_recording() { view_.stop_recording(); }

  // ---- Calibrate ----------------------------------------------------------------------------
  // Ctrl+Z in the Devices tab: undoes an applied calibration, or says where to undo the layout's
  // later change.
  void undo_calibration();
  void report_calibration(const std::string& text, bool is_error) { report("Calibrate: " + text, is_error); }

  // A line in the status bar.
  void report(const std::string& text, bool is_error) {
    showing_error_ = is_error;
    if (status_) status_(text, is_error);
  }

 private:
  CurrentLayout& layout_;
  StatusFn status_;
  DevicesViewModel view_;
  CalibrationStep calibration_;  // records through the same rig
  std::vector<SceneItem> ghosts_;
  std::string last_calibration_message_;
  std::uint64_t seen_messages_ = 0;
  bool auto_started_ = false;
  bool fallback_pending_ = false;
  bool showing_error_ = false;  // the tab's latest status line is an error
};

}  // namespace lmc::ui
