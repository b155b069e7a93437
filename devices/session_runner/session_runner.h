#pragma once
// Runs a subject session: the protocol's trials in order, each through the one trial
// engine, a pre-flight before the first trial and after every layout change, a quality verdict
// seconds after each trial, redo, and resume after a crash. Every state change goes through the
// session folder's journal first, so whatever happens to this process, the folder says what was
// recorded and what is still to do. No terminal or UI here: `lmc session run` and the Record tab
// drive it and show its snapshots.
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <stop_token>
#include <string>

#include <nlohmann/json.hpp>

#include "core/calibration/calibrate_trial.h"
#include "core/session/protocol.h"
#include "core/session/session_folder.h"
#include "core/session/trial_quality.h"
#include "devices/device_hub.h"
#include "devices/frame_tap.h"
#include "devices/record/trial_engine.h"
#include "devices/session_runner/preflight.h"
#include "devices/sim/sim_config.h"

namespace lmc::devices {

struct SessionRunOptions {
  std::string backend = "sim";  // sim | leapc | replay:FILE
  bool fast = false;            // simulated time (sim and replay only)
  SimConfig sim;                // the simulated rig's base settings (motion comes from the protocol)
  double stream_timeout_s = 10;
  double countdown_s = 0;
  double preflight_timeout_s = 5;
  std::optional<std::filesystem::path> vicon_export_dir;  // where Vicon writes <trial>.trc/.c3d
  // A hub someone else owns and keeps running (the workbench's live rig), used for every
  // pre-flight and trial instead of opening the backend again: two LeapC connections to the same
  // controllers would fight over them. Its layout's slot names must be the session's, in order
  // (the pre-flight says so when they are not); it must outlive the runner.
  DeviceHub* external_hub = nullptr;
};

// A block's calibration step as the runner did it: recorded, fitted, not yet applied.
struct BlockCalibration {
  int trial = -1;  // the plan trial whose block this is
  std::string block;
  int attempt = 0;
  std::string trial_name;  // Calib_<block>NN
  std::string failure;     // why there is no fit (the recording failed, too little hand): empty when fitted
  std::optional<TrialCalibration> fit;
  nlohmann::json summary;             // calibration_summary_json of the fit (null without one)
  std::string residual_table;         // residual_table, for people
  std::vector<std::string> warnings;  // every warning a person must see before applying
  bool ok() const { return fit.has_value(); }
};

// What happened to one attempt, as the runner journaled it.
struct AttemptResult {
  int trial = -1;
  int attempt = 0;
  std::string outcome;  // completed | aborted | failed | interrupted
  std::string reason;
  std::optional<QualityReport> quality;  // absent when nothing could be assessed
  std::int64_t frames = 0;               // rows the recorder wrote (0: nothing to keep)
  bool reached_go = false;               // the subject was told to go (the window opened)
  std::string verdict() const;           // the quality verdict, or "fail" when there is none
};

// The verdict's one reason when the operator ended a trial before go ("aborted before go — no
// data"): the countdown is not recorded, so nothing is judged and no controller is blamed.
std::string before_go_reason(const std::string& outcome);

class SessionRunner {
 public:
  SessionRunner(SessionFolder& folder, SessionRunOptions options);
  ~SessionRunner();
  SessionRunner(const SessionRunner&) = delete;
  SessionRunner& operator=(const SessionRunner&) = delete;

  const SessionFolder& folder() const { return folder_; }
  const Protocol& protocol() const { return protocol_; }
  const std::vector<PlannedTrial>& plan() const { return plan_; }
  // The layout of trial `i`'s block, as the manifest keeps it (fixed after construction, so any
  // thread may read it while a trial runs).
  const Layout& layout(int i) const { return layout_for(i); }

  // True when trial `i` starts a block whose pre-flight has not passed (or been overridden) yet.
  bool needs_preflight(int i) const;
  // Runs (and journals) the pre-flight for the block of trial `i`.
  PreflightReport preflight(int i, std::stop_token stop = {});
  // The operator goes ahead despite red lines; the reason is journaled.
  void override_preflight(int i, const std::string& reason);

  // Records trial `i` once (a new attempt), assesses it and journals every step. Throws only for
  // a programming error; device and disk trouble end the attempt with its outcome and reason.
  // `live_tap` (the live fused hand, frame_tap.h) sees every frame of the trial's hub while it
  // records; it must be built for layout(i) and is detached before run_trial returns.
  // `abort_reason`, asked once when the stop token ended the trial: a non-empty answer journals
  // the attempt as aborted with that reason instead of interrupted (the operator's Esc).
  AttemptResult run_trial(int i, std::stop_token stop = {},
                          const std::function<void(const TrialSnapshot&)>& on_status = {}, FrameTap* live_tap = nullptr,
                          const std::function<std::string()>& abort_reason = {});
  // The operator keeps the last attempt of trial `i`.
  void accept(int i);
  // The last attempt of trial `i` goes under superseded/; the trial is pending again.
  void redo(int i);
  void note(int i, const std::string& text);

  // The calibration step (Protocol::calibration). True when trial `i`'s block has one
  // and it is not done (applied, or the nominal layout kept) in this session's journal. Run it
  // after the block's pre-flight and before its first trial.
  bool needs_calibration(int i) const;
  // Journals the start, records a still open hand for the protocol's duration as trial
  // Calib_<block>NN (the same trial engine and files as any trial) and calibrates it against the
  // block's nominal layout: with the trial's Vicon file (<trial>.trc in vicon_export_dir or the
  // session folder) when there is one, else the controllers against each other. Applies nothing: the operator looks
  // first.
  BlockCalibration calibrate_block(int i, std::stop_token stop = {},
                                   const std::function<void(const TrialSnapshot&)>& on_status = {});
  // The fit becomes the block's layout (journaled; the next trials record with it).
  void apply_calibration(const BlockCalibration& c);
  // The block keeps its nominal layout; the reason (and the fit, if any) are journaled.
  void keep_nominal_layout(int i, const std::string& reason, const BlockCalibration* c = nullptr);

  // What the operator sets up before trial `i`'s block: the layout's name and each controller's
  // target position, in words.
  std::string block_instructions(int i) const;

 private:
  // The hub a recording runs on (owned or borrowed) and its simulator, if it plays one.
  struct RecordingHub;
  // A new hub of trial `i`'s block with its source opened; `motion` overrides the trial's simulated
  // motion ("horizontal/static").
  std::unique_ptr<RecordingHub> make_recording_hub(int i, double duration_s, std::uint64_t seed,
                                                   const std::string& motion = {}) const;
  // The hub one recording of trial `i` (a trial or its block's calibration) runs on: the caller's
  // hub when it gave one, the block's hub of real controllers while it is up, else one made for it.
  std::unique_ptr<RecordingHub> hub_for_recording(int i, double duration_s, std::uint64_t seed,
                                                  const std::string& motion = {}) const;
  const Layout& layout_for(int i) const;
  Layout nominal_layout_for(int i) const;  // before any calibration of the block
  std::uint64_t bytes_still_needed(int from) const;
  std::optional<std::string> vicon_target() const;  // "HOST[:PORT]" when the session triggers Vicon
  // The trial engine's settings for one recording of this session (a trial or a calibration trial):
  // folder, timing, the Vicon trigger with the cue as its description, the session's sidecar notes.
  TrialEngineConfig engine_config(const std::string& name, double seconds, const std::string& operator_cue, int attempt,
                                  const std::string& block) const;

  SessionFolder& folder_;
  SessionRunOptions options_;
  Protocol protocol_;
  std::vector<PlannedTrial> plan_;
  std::map<std::string, Layout> layouts_;       // by layout key, from the manifest
  std::set<std::string> cleared_blocks_;        // pre-flight passed or overridden in this run
  std::unique_ptr<RecordingHub> hardware_hub_;  // leapc: one hub per block, kept across its trials
  std::string hardware_block_;
};

}  // namespace lmc::devices
