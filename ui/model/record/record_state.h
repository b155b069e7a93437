#pragma once
// The Record tab's state, without ImGui: one subject session folder, the session
// runner that records it, and the one piece of work that may run at a time (a pre-flight or a
// trial) on a worker thread. The tab reads this and calls its actions; it never touches the folder,
// the runner or a device.
//
// Threading: while the worker runs, only it touches the runner and the folder (their journal
// writes are not shared); the UI thread reads `state()`, a copy refreshed whenever the worker is
// idle, and the latest trial snapshot the worker published. Every action refuses (returns a reason)
// while the worker is busy, so the two never meet. The worker shares ownership of what it uses
// (folder, runner, live fusion, abort flag), so nothing it holds can go away under it, whatever
// order the model is taken down in; a lent hub stays the rig's, given back only after the join.
//
// The rules are the CLI's (`lmc session run`): a pass or warn verdict accepts the trial; a fail
// waits for the operator, who redoes it or accepts it anyway (journaled); a redo keeps the earlier
// attempt under superseded/.
#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/processing/online_fusion.h"
#include "core/session/session_folder.h"
#include "devices/fusion/live_fusion.h"
#include "devices/record/trial_engine.h"
#include "devices/session_runner/session_runner.h"
#include "ui/model/devices/live_hands.h"
#include "ui/model/jobs/background_job.h"
#include "ui/model/shell/status_report.h"

namespace lmc::ui {

// What the operator chooses for recording (not part of the session folder).
struct RecordSettings {
  std::string backend = "sim";  // sim | leapc | replay:FILE
  bool fast = false;            // simulated time (sim and replay only)
  double countdown_s = 3;       // seconds between Start and the first recorded second
  devices::SimConfig sim;
  // Record through the workbench's live rig (LiveRig::lend) instead of opening the backend again:
  // the tab sets it for leapc, where a second connection would fight the Devices tab's for the
  // same controllers. Needs the model to be given the rig.
  bool share_rig_hub = false;
};

// What the worker did, for poll().
struct RecordWorkResult {
  std::optional<devices::PreflightReport> preflight;
  std::optional<devices::AttemptResult> attempt;
  std::optional<devices::BlockCalibration> calibration;
};

class LiveRig;

class RecordState {
 public:
  // `rig` (optional, must outlive the model): the workbench's live rig, lent for sessions whose
  // settings share its hub.
  explicit RecordState(LiveRig* rig = nullptr);
  ~RecordState();
  RecordState(const RecordState&) = delete;
  RecordState& operator=(const RecordState&) = delete;

  // ---- the session ---------------------------------------------------------------------------
  // Both return an error text ("" when done). A session already open is closed first.
  std::string create(const std::filesystem::path& dir, const NewSessionSpec& spec, const RecordSettings& settings);
  std::string open(const std::filesystem::path& dir, const RecordSettings& settings);
  void close();
  bool has_session() const { return folder_ != nullptr; }
  const std::filesystem::path& dir() const { return dir_; }
  // A copy of the folder's state (refreshed whenever the worker is idle). Valid while has_session().
  const SessionState& state() const { return state_; }
  // Trials found cut off when the session was opened: the plain notice the operator reads first.
  const std::vector<std::string>& recovered() const { return recovered_; }
  // Set when an existing folder was opened (not created): what happened and where it continues
  // (resume_notice.h). Empty for a new session.
  const std::vector<std::string>& resume_notice() const { return resume_notice_; }
  const RecordSettings& settings() const { return settings_; }

  // ---- where we are -----------------------------------------------------------------------------
  // The trial Start records next: the selected one, else the first not accepted (-1: all done).
  int current_trial() const;
  void select(int i);  // -1 clears the selection (back to the protocol's order)
  int accepted_count() const { return has_session() ? state_.count(TrialStatus::kAccepted) : 0; }
  bool finished() const { return has_session() && state_.next_trial() < 0; }
  const TrialType& trial_type(int i) const;
  // Plain words: which layout to set up for the current trial's block, with target positions.
  std::string block_instructions() const;

  // ---- pre-flight ---------------------------------------------------------------------------------
  bool needs_preflight() const;  // the current trial's block has not been cleared in this run
  std::string start_preflight();
  std::string override_preflight(const std::string& reason);
  const std::optional<devices::PreflightReport>& last_preflight() const { return last_preflight_; }

  // ---- the block's calibration (protocols with a calibration step) ------------------------
  // True after the block's pre-flight when its calibration is not done: Start then records the
  // still-hand calibration trial instead of the block's first trial.
  bool needs_calibration() const;
  bool calibrating() const { return busy() && calibrating_; }
  // Records and fits the block's calibration trial on the worker. The result waits in
  // pending_calibration() for the operator: apply it, calibrate again, or keep the nominal layout.
  std::string start_calibration();
  const std::optional<devices::BlockCalibration>& pending_calibration() const { return pending_calibration_; }
  std::string apply_calibration();
  std::string keep_nominal_layout(const std::string& reason);

  // ---- trials -------------------------------------------------------------------------------------
  // Records the current trial (a new attempt). Refused while busy or before the pre-flight.
  std::string start_trial();
  void stop_trial();  // the trial ends as interrupted; its rows are kept
  // Esc: the trial ends as aborted by the operator (journaled so; its rows are kept, the verdict
  // is fail and the trial waits for a redo). Returns why not when nothing records.
  std::string abort_trial();
  bool busy() const { return job_.running(); }
  bool recording() const { return busy() && recording_trial_ >= 0; }
  // The block's pre-flight is being run on the worker (needs_preflight() is false meanwhile).
  bool preflight_running() const { return busy() && recording_trial_ < 0 && !calibrating_; }
  int recording_trial() const { return recording_trial_; }
  // The latest status of the trial being recorded (phase, countdown, per-device rows).
  const std::optional<devices::TrialSnapshot>& live() const { return live_; }
  // Each controller's latest hand in the world frame (live_hands.h), while recording.
  const std::vector<LiveHand>& live_hands() const { return live_hands_; }
  // The controllers fused into one hand while recording: every frame of the trial's hub goes
  // through the causal default fusion on a worker thread of its own (devices/fusion/live_fusion.h),
  // fingers with how many controllers see them now; and its latency from a frame's arrival at
  // the hub to the fused hand (p50/p95/max over the latest frames).
  const std::optional<FusedHand>& live_fused() const { return live_fused_; }
  const devices::LiveFusionStats& fusion_stats() const { return fusion_stats_; }
  // The layout of the current (or recording) trial's block; null without a session.
  const Layout* current_layout() const;
  // The last attempt this run recorded, with its verdict; and which trial it was.
  const std::optional<devices::AttemptResult>& last_attempt() const { return last_attempt_; }
  // Keeps the last attempt despite a fail verdict (the operator's decision, journaled as a note).
  // An attempt without a frame is never kept: there is nothing to keep (returns why).
  std::string accept_last();
  // Enter on a failed attempt does not keep it: it asks, naming what failed, and the answer comes
  // from answer_accept() (the tab's default is No, so Enter twice never keeps a failed trial).
  // Returns why not when there is nothing to ask about (no attempt, no frames, busy); "" when
  // the attempt is already kept or the question is now open.
  std::string ask_accept();
  const std::string& accept_question() const { return accept_question_; }  // "" when none is open
  std::string answer_accept(bool keep);  // keep: accept_last(); else the question closes
  // Records trial `i` again: its current attempt moves under superseded/ (i = -1: the trial picked
  // in the list if it has been recorded, else the last one recorded in this run).
  std::string redo(int i = -1);
  // N: a one-line note on the trial being recorded, else the last one recorded, else the current
  // one, journaled with it. While a trial records the note waits and is journaled as soon as the
  // worker is done with the folder (nothing the operator types is lost).
  std::string add_note(const std::string& text);
  int note_trial() const;  // the trial add_note() writes to (-1: none)

  // Once a frame: takes the worker's snapshots and, when it finished, its result (accepting a
  // pass or warn, refreshing the state). Returns one line for the status bar when something ended:
  // an error when the job failed, the pre-flight or calibration failed, the attempt's verdict is
  // fail, or the attempt or a note could not be kept.
  StatusReport poll();

 private:
  // What the worker is doing, for a refusal: which job runs and when the operator can act again.
  std::string busy_reason() const;
  std::string adopt(SessionFolder folder, const RecordSettings& settings, bool resumed);
  void refresh_state();

  LiveRig* rig_ = nullptr;
  bool rig_borrowed_ = false;
  std::shared_ptr<SessionFolder> folder_;           // shared with the worker, as are runner_, live_fusion_
  std::shared_ptr<devices::SessionRunner> runner_;  // and abort_requested_
  std::filesystem::path dir_;
  SessionState state_;
  std::vector<std::string> recovered_;
  std::vector<std::string> resume_notice_;
  RecordSettings settings_;
  int selected_ = -1;
  int recording_trial_ = -1;
  std::optional<devices::TrialSnapshot> live_;
  std::vector<LiveHand> live_hands_;
  void write_pending_notes();
  void give_back_rig();
  std::shared_ptr<devices::LiveFusion> live_fusion_;  // per trial, with its block's layout
  std::optional<FusedHand> live_fused_;
  devices::LiveFusionStats fusion_stats_;
  std::shared_ptr<std::atomic<bool>> abort_requested_ =
      std::make_shared<std::atomic<bool>>(false);           // read by the worker when the trial stops
  std::vector<std::pair<int, std::string>> pending_notes_;  // typed while the worker held the folder
  std::string last_note_error_;
  std::optional<devices::PreflightReport> last_preflight_;
  std::optional<devices::AttemptResult> last_attempt_;
  std::string accept_question_;
  std::optional<devices::BlockCalibration> pending_calibration_;
  bool calibrating_ = false;
  bool job_handled_ = true;                                      // the finished job's result was taken by poll()
  BackgroundJob<RecordWorkResult, devices::TrialSnapshot> job_;  // last: joined first
};

}  // namespace lmc::ui
