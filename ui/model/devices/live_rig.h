#pragma once
// The workbench's one device hub: owned by the application (WorkbenchContext), not by
// a tab, so the Devices and Record tabs see the same controllers, the same slot assignments and
// the same test recording. Starting and stopping a backend ("sim", "leapc", "replay:FILE") and
// recording a trial are actions on it.
//
// It streams with the workbench's layout (CurrentLayout, published by the Layout tab): when that
// layout changes, poll() restarts a running backend with it (serial bindings are kept by slot
// name) and says so in a message; while a trial records, the restart waits until it ends.
//
// Trials go through the one TrialEngine on a worker thread (RigTrialJob); names are never
// overwritten (next_free_trial_name picks trial-2, trial-3, …). UI thread only, except what the
// trial's worker does to the hub (the hub is thread-safe).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/layout/layout.h"
#include "devices/device_hub.h"
#include "devices/fusion/live_fusion.h"
#include "devices/sim/sim_config.h"
#include "ui/model/current_layout.h"
#include "ui/model/devices/rig_trial_job.h"

namespace lmc::ui {

class LiveRig {
 public:
  explicit LiveRig(const CurrentLayout& layout);
  ~LiveRig();
  LiveRig(const LiveRig&) = delete;
  LiveRig& operator=(const LiveRig&) = delete;

  // ---- backend ------------------------------------------------------------------------------
  // Starts a backend with the current layout; a running one (and its trial) is stopped first.
  // Returns an error text (empty when fine).
  std::string start(const std::string& backend, const devices::SimConfig& sim = {});
  // Stops the trial (if any, keeping what it wrote) and the backend.
  void stop();
  bool running() const { return hub_ != nullptr; }
  const std::string& backend() const { return backend_; }
  double running_seconds() const;
  // The shared hub (null while stopped): every client reads the same controllers through it.
  devices::DeviceHub* hub() { return hub_.get(); }
  const devices::DeviceHub* hub() const { return hub_.get(); }
  // The live fused hand of the rig's controllers (devices/fusion/live_fusion.h: every frame of
  // the hub on a worker thread of its own); null while stopped or when the layout cannot be fused.
  const devices::LiveFusion* fusion() const { return fusion_.get(); }
  // The layout the rig streams with: the workbench's plus the serials bound to its slots.
  const Layout& layout() const { return hub_ ? hub_->layout() : layout_; }
  // Binds a controller to a slot (the binding becomes part of the rig's layout).
  std::string assign(const std::string& serial, const std::string& slot);

  // Once a frame: picks up a layout change (restart, message), polls the trial. Idempotent, so
  // every client may call it.
  void poll();
  // The latest rig, device and trial messages, oldest first (bounded): one log every client reads.
  const std::vector<std::string>& messages() const { return messages_; }
  // How many messages were ever said: a client that saw N shows the last (total − N) as new.
  std::uint64_t messages_total() const { return messages_total_; }

  // ---- lending the hub ----------------------------------------------------------------------------
  // The Record tab records a session through this hub (one LeapC connection for the whole
  // workbench): while lent, start(), stop(), a test recording and a layout restart are refused or
  // wait, so the hub stays valid and nobody else installs a recorder on it. lend() starts
  // `backend` when the rig runs another (or none) and returns the hub, or null with `error` set.
  devices::DeviceHub* lend(const std::string& backend, std::string& error);
  void give_back();
  bool lent() const { return lent_; }

  // ---- trial --------------------------------------------------------------------------------
  // Records `trial` into `dir` through the TrialEngine (the rig's layout, `seconds` long). Never
  // overwrites: a taken name becomes trial-2, trial-3, … (see trial_name()). Returns an error
  // text, empty when the trial started.
  std::string start_trial(const std::filesystem::path& dir, const std::string& trial, double seconds);
  void stop_trial() { trial_.request_stop(); }
  // True from start_trial until poll() has reported the ended trial (its summary and messages):
  // a caller that sees false can always take the summary, even if the job ended mid-poll.
  bool recording() const { return trial_.running() || (job_finished(trial_.state()) && !trial_reported_); }
  const RigTrialJob& trial() const { return trial_; }
  // The name the current (or last) trial got.
  const std::string& trial_name() const { return trial_.trial(); }
  // One line on how the last trial ended ("" while none ended since the last call).
  std::string take_trial_summary();

 private:
  void say(std::string text);
  void apply_layout_change();
  void finish_trial_if_done();

  const CurrentLayout& current_;
  std::uint64_t layout_version_ = 0;
  bool layout_change_pending_ = false;
  Layout layout_;                                // the workbench's layout with this rig's serial bindings
  std::unique_ptr<devices::LiveFusion> fusion_;  // before hub_: outlives its registration on it
  std::shared_ptr<devices::DeviceHub> hub_;      // shared with a test recording's worker
  std::string backend_;
  devices::SimConfig sim_config_;
  std::int64_t started_ns_ = 0;
  std::vector<std::string> messages_;
  std::uint64_t messages_total_ = 0;
  bool trial_reported_ = true;
  bool lent_ = false;
  std::string trial_summary_;
  RigTrialJob trial_;  // after hub_: destroyed (joined) before the hub it records from
};

}  // namespace lmc::ui
