#pragma once
// Non-drawing logic of the workbench's Devices tab, held by its state (devices_state.h): a client
// of the workbench's live rig (LiveRig, shared with the Record tab). It turns hub snapshots into table rows and
// world-frame hands for the live view and drives the rig's test recording (the one TrialEngine on
// a worker thread). No ImGui here, so tests drive it directly; the tab only draws, with the
// shared scene camera (ui/scene/orbit_camera.h) and bones (ui/scene/scene_items.h).
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/hand/hand_frame.h"
#include "core/layout/layout.h"
#include "devices/sim/sim_config.h"
#include "ui/model/devices/live_hands.h"
#include "ui/model/devices/live_rig.h"

namespace lmc::ui {

struct DeviceRow {
  std::string serial;
  std::string slot;  // empty: unassigned
  int slot_index = -1;
  std::string backend;
  std::string model;          // "Leap Motion Controller 2", …; empty when the backend did not say
  std::string model_warning;  // the controller is not the model its slot is laid out as (DeviceStatus)
  std::string tracking_mode;  // "desktop", "screen-top", …; empty until the backend reports it
  std::string status;         // "streaming", "no hand", "stalled", "disconnected", "unassigned"
  double rate_hz = 0;
  double age_ms = -1;
  bool hand_present = false;
  std::int64_t frames = 0;
  std::int64_t dropped = 0;
  int colour = 0;     // index into device_colour()
  bool warn = false;  // also when its slot cannot see the hand (DevicesViewModel::layout_warnings)
};

// Where the current (or last) test recording is, from the engine's latest status.
struct RecordingProgress {
  std::string trial;
  std::string phase;  // trial_phase_name(): "waiting_for_streams", "recording", …
  double recording_s = 0;
  double remaining_s = 0;
  std::int64_t frames_written = 0;
  std::int64_t frames_dropped = 0;
};

class DevicesViewModel {
 public:
  static constexpr double kDefaultTrialSeconds = 10;

  explicit DevicesViewModel(LiveRig& rig);

  LiveRig& rig() { return rig_; }
  // The rig's layout: the workbench's (Layout tab) with the controllers' serial bindings.
  const Layout& layout() const { return rig_.layout(); }
  // Starts a backend ("sim", "leapc", "replay:FILE") on the shared rig; stops the previous one.
  // Returns an error text (empty when fine).
  std::string start(const std::string& backend, const devices::SimConfig& sim = {});
  void stop();
  bool running() const { return rig_.running(); }
  const std::string& backend() const { return rig_.backend(); }
  double running_seconds() const { return rig_.running_seconds(); }

  // Polls the rig (layout changes, trial status) and pulls a fresh snapshot; once per UI frame.
  void refresh();
  const std::vector<DeviceRow>& rows() const { return rows_; }
  const std::vector<LiveHand>& hands() const { return hands_; }
  // The rig's controllers fused into one hand (the Record tab's live fusion, on the rig's hub)
  // and its latency; nullopt / empty stats while the rig is stopped.
  const std::optional<FusedHand>& fused() const { return fused_; }
  const devices::LiveFusionStats& fusion_stats() const { return fusion_stats_; }
  const std::vector<std::string>& messages() const { return rig_.messages(); }
  std::vector<std::string> slot_choices() const;
  std::string assign(const std::string& serial, const std::string& slot);
  // True once every layout slot has streamed for at least a second (rates are meaningful).
  bool all_streaming() const { return all_streaming_; }
  // One line per controller of the rig's layout that cannot see the hand region at all (core's
  // blind_controllers), naming it and why: its "no hand" is the layout's doing, not a broken
  // controller. Empty when every controller can see the hand. Kept up to date by refresh().
  const std::vector<std::string>& layout_warnings() const { return layout_warnings_; }

  // Test recording of `seconds` into `dir` through the rig's trial engine (trial name checked).
  // Never overwrites: when `trial` has files in `dir` the next free name (trial-2, trial-3, …) is
  // used, see recording_trial(). Errors come back as text.
  std::string start_recording(const std::filesystem::path& dir, const std::string& trial,
                              double seconds = kDefaultTrialSeconds);
  // Asks the engine to stop: the trial ends "interrupted", keeping every row written.
  void stop_recording() { rig_.stop_trial(); }
  bool recording() const { return rig_.recording(); }
  const std::string& recording_trial() const { return rig_.trial_name(); }
  std::optional<RecordingProgress> recording_progress() const;
  // How the last trial ended, once ("" otherwise): outcome, reason, frames and file.
  std::string take_recording_summary() { return rig_.take_trial_summary(); }

 private:
  LiveRig& rig_;
  std::vector<DeviceRow> rows_;
  std::vector<LiveHand> hands_;
  std::optional<FusedHand> fused_;
  devices::LiveFusionStats fusion_stats_;
  bool all_streaming_ = false;
  std::vector<std::string> layout_warnings_;
  std::vector<int> blind_slots_;         // layout indices of the controllers layout_warnings_ name
  std::optional<Layout> warned_layout_;  // the layout layout_warnings_ describe
};

}  // namespace lmc::ui
