#include "ui/model/record/record_state.h"

#include <utility>

#include "core/common/error.h"
#include "ui/model/devices/live_rig.h"
#include "ui/model/record/resume_notice.h"

namespace lmc::ui {
namespace {

// The journaled reason of a trial the operator aborted (Esc): the attempt is kept and redone.
constexpr const char* kAbortedByOperator = "aborted by the operator";

}  // namespace

RecordState::RecordState(LiveRig* rig) : rig_(rig) {}

RecordState::~RecordState() {
  close();
}

std::string RecordState::adopt(SessionFolder folder, const RecordSettings& settings, bool resumed) {
  folder_ = std::make_shared<SessionFolder>(std::move(folder));
  try {
    devices::SessionRunOptions options;
    options.backend = settings.backend;
    options.fast = settings.fast;
    options.sim = settings.sim;
    options.countdown_s = settings.countdown_s;
    if (settings.share_rig_hub) {
      if (rig_ == nullptr) throw Error("no live rig to record through");
      std::string why;
      options.external_hub = rig_->lend(settings.backend, why);
      if (options.external_hub == nullptr) throw Error("cannot use the " + settings.backend + " controllers: " + why);
      rig_borrowed_ = true;
    }
    runner_ = std::make_shared<devices::SessionRunner>(*folder_, options);
  } catch (const std::exception& e) {
    folder_.reset();  // releases the folder's lock
    give_back_rig();
    return e.what();
  }
  settings_ = settings;
  dir_ = folder_->dir();
  recovered_ = folder_->recovered();
  selected_ = -1;
  live_.reset();
  last_preflight_.reset();
  last_attempt_.reset();
  refresh_state();
  resume_notice_ = resumed ? ui::resume_notice(state_, recovered_) : std::vector<std::string>{};
  return {};
}

std::string RecordState::create(const std::filesystem::path& dir, const NewSessionSpec& spec,
                                const RecordSettings& settings) {
  if (busy()) return busy_reason();
  close();
  try {
    return adopt(SessionFolder::create(dir, spec), settings, false);
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string RecordState::open(const std::filesystem::path& dir, const RecordSettings& settings) {
  if (busy()) return busy_reason();
  close();
  try {
    return adopt(SessionFolder::open(dir), settings, true);
  } catch (const std::exception& e) {
    return e.what();
  }
}

void RecordState::give_back_rig() {
  if (rig_borrowed_ && rig_ != nullptr) rig_->give_back();
  rig_borrowed_ = false;
}

void RecordState::close() {
  // The worker uses the runner, the folder, the live fusion and a lent hub: it ends first.
  job_.cancel_and_join();
  // A note typed while the last trial recorded still reaches the journal.
  if (runner_ && !pending_notes_.empty()) write_pending_notes();
  pending_notes_.clear();
  live_fusion_.reset();
  runner_.reset();
  give_back_rig();
  folder_.reset();
  state_ = {};
  recovered_.clear();
  resume_notice_.clear();
  recording_trial_ = -1;
  selected_ = -1;
  // Everything that described the closed session goes with it: a verdict, pre-flight or
  // calibration left here would be read against the next session's (or no) trials.
  live_.reset();
  live_hands_.clear();
  live_fused_.reset();
  fusion_stats_ = {};
  last_preflight_.reset();
  last_attempt_.reset();
  accept_question_.clear();
  pending_calibration_.reset();
  calibrating_ = false;
  job_handled_ = true;
  last_note_error_.clear();
}

void RecordState::refresh_state() {
  if (folder_) state_ = folder_->state();
}

int RecordState::current_trial() const {
  if (!has_session()) return -1;
  if (selected_ >= 0 && selected_ < static_cast<int>(state_.trials.size())) return selected_;
  return state_.next_trial();
}

void RecordState::select(int i) {
  selected_ = (has_session() && i >= 0 && i < static_cast<int>(state_.trials.size())) ? i : -1;
}

const TrialType& RecordState::trial_type(int i) const {
  const auto& plan = state_.trials.at(static_cast<size_t>(i)).plan;
  return state_.protocol.trial_types.at(static_cast<size_t>(plan.trial_type));
}

std::string RecordState::block_instructions() const {
  const int i = current_trial();
  if (!runner_ || i < 0) return {};
  return runner_->block_instructions(i);
}

bool RecordState::needs_preflight() const {
  const int i = current_trial();
  // runner_ is read, not changed; while the worker runs the answer is not needed.
  return runner_ && i >= 0 && !busy() && runner_->needs_preflight(i);
}

std::string RecordState::busy_reason() const {
  if (recording()) return "a trial is recording; stop it first (Space, or Esc to abort)";
  if (calibrating()) return "the block's calibration is recording; wait for it to finish";
  // A Space pressed while the controllers, Vicon and disk are checked lands here: it is not lost
  // silently, and the operator learns when pressing again will start the trial.
  if (preflight_running()) return "the pre-flight is still running; Start [Space] comes when every line is green";
  return "the worker is busy";
}

std::string RecordState::start_preflight() {
  if (!has_session()) return "open or create a session first";
  if (busy()) return busy_reason();
  const int i = current_trial();
  if (i < 0) return "every trial is accepted";
  recording_trial_ = -1;
  job_handled_ = false;
  job_.start([folder = folder_, runner = runner_, i](std::stop_token stop, JobChannel<devices::TrialSnapshot>&) {
    RecordWorkResult r;
    r.preflight = runner->preflight(i, stop);
    return r;
  });
  return {};
}

std::string RecordState::override_preflight(const std::string& reason) {
  if (busy()) return busy_reason();
  if (reason.find_first_not_of(" \t") == std::string::npos) return "type the reason for going ahead; it is journaled";
  const int i = current_trial();
  if (!runner_ || i < 0) return "no trial to record";
  try {
    runner_->override_preflight(i, reason);
  } catch (const std::exception& e) {
    return e.what();
  }
  refresh_state();
  return {};
}

std::string RecordState::start_trial() {
  if (!has_session()) return "open or create a session first";
  if (busy()) return busy_reason();
  const int i = current_trial();
  if (i < 0) return "every trial is accepted";
  if (state_.trials[static_cast<size_t>(i)].status == TrialStatus::kAccepted)
    return state_.trials[static_cast<size_t>(i)].plan.name + " is accepted; redo it (R) to record it again";
  if (runner_->needs_preflight(i)) return "run the pre-flight for this layout first (or override it with a reason)";
  if (runner_->needs_calibration(i)) return "calibrate this layout first (or keep its nominal layout, with a reason)";
  try {
    live_fusion_ = std::make_shared<devices::LiveFusion>(runner_->layout(i));
  } catch (const std::exception& e) {
    return "the block's layout cannot be fused live: " + std::string(e.what());
  }
  recording_trial_ = i;
  accept_question_.clear();
  resume_notice_.clear();  // it described the folder as opened; a new attempt has begun
  live_.reset();
  live_fused_.reset();
  fusion_stats_ = {};
  abort_requested_ = std::make_shared<std::atomic<bool>>(false);
  // Shown as recording at once; the folder's own state says so when the worker is done.
  state_.trials[static_cast<size_t>(i)].status = TrialStatus::kRecording;
  job_handled_ = false;
  job_.start([folder = folder_, runner = runner_, i, fusion = live_fusion_, aborting = abort_requested_](
                 std::stop_token stop, JobChannel<devices::TrialSnapshot>& channel) {
    RecordWorkResult r;
    r.attempt = runner->run_trial(
        i, stop, [&channel](const devices::TrialSnapshot& s) { channel.report(s); }, fusion.get(),
        [aborting] { return aborting->load() ? std::string(kAbortedByOperator) : std::string(); });
    return r;
  });
  return {};
}

bool RecordState::needs_calibration() const {
  if (!has_session() || busy()) return false;
  const int i = current_trial();
  return i >= 0 && !runner_->needs_preflight(i) && runner_->needs_calibration(i);
}

std::string RecordState::start_calibration() {
  if (!has_session()) return "open or create a session first";
  if (busy()) return busy_reason();
  const int i = current_trial();
  if (i < 0) return "every trial is accepted";
  if (runner_->needs_preflight(i)) return "run the pre-flight for this layout first (or override it with a reason)";
  if (!runner_->needs_calibration(i)) return "this layout needs no calibration";
  pending_calibration_.reset();
  resume_notice_.clear();
  calibrating_ = true;
  live_.reset();
  job_handled_ = false;
  job_.start(
      [folder = folder_, runner = runner_, i](std::stop_token stop, JobChannel<devices::TrialSnapshot>& channel) {
        RecordWorkResult r;
        r.calibration =
            runner->calibrate_block(i, stop, [&channel](const devices::TrialSnapshot& s) { channel.report(s); });
        return r;
      });
  return {};
}

std::string RecordState::apply_calibration() {
  if (busy()) return busy_reason();
  if (!pending_calibration_) return "no calibration to apply";
  if (!pending_calibration_->ok()) return "the calibration failed: " + pending_calibration_->failure;
  try {
    runner_->apply_calibration(*pending_calibration_);
  } catch (const std::exception& e) {
    return e.what();
  }
  pending_calibration_.reset();
  refresh_state();
  return {};
}

std::string RecordState::keep_nominal_layout(const std::string& reason) {
  if (busy()) return busy_reason();
  const int i = current_trial();
  if (i < 0) return "every trial is accepted";
  if (reason.find_first_not_of(" \t") == std::string::npos)
    return "say why the nominal layout is kept (it is journaled)";
  try {
    runner_->keep_nominal_layout(i, reason, pending_calibration_ ? &*pending_calibration_ : nullptr);
  } catch (const std::exception& e) {
    return e.what();
  }
  pending_calibration_.reset();
  refresh_state();
  return {};
}

void RecordState::stop_trial() {
  if (recording() || calibrating()) job_.cancel();
}

std::string RecordState::abort_trial() {
  if (!recording()) return "no trial is recording";
  abort_requested_->store(true);
  job_.cancel();
  return {};
}

int RecordState::note_trial() const {
  if (!has_session()) return -1;
  if (recording()) return recording_trial_;
  if (last_attempt_) return last_attempt_->trial;
  return current_trial();
}

std::string RecordState::add_note(const std::string& text) {
  if (!has_session()) return "open or create a session first";
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "the note is empty";
  const auto last = text.find_last_not_of(" \t");
  const std::string line = text.substr(first, last - first + 1);
  if (line.find('\n') != std::string::npos) return "a note is one line";
  const int i = note_trial();
  if (i < 0) return "no trial to note";
  pending_notes_.emplace_back(i, line);
  // The worker owns the folder while it runs: the note waits for it (poll() writes it).
  if (busy()) return {};
  write_pending_notes();
  return std::exchange(last_note_error_, {});
}

void RecordState::write_pending_notes() {
  for (const auto& [i, line] : pending_notes_) {
    try {
      runner_->note(i, line);
    } catch (const std::exception& e) {
      // Kept in the status line: the operator reads that the note did not reach the journal.
      last_note_error_ = "note not journaled: " + std::string(e.what());
    }
  }
  pending_notes_.clear();
  refresh_state();
}

namespace {

// What the operator reads before keeping a failed attempt, or why it cannot be kept.
std::string attempt_failure(const devices::AttemptResult& a) {
  std::string what = std::to_string(a.frames) + " frame" + (a.frames == 1 ? "" : "s");
  if (a.quality && !a.quality->reasons.empty()) return what + ": " + a.quality->reasons.front();
  return what + ": " + (a.reason.empty() ? a.outcome : a.reason);
}

}  // namespace

std::string RecordState::accept_last() {
  accept_question_.clear();
  if (busy()) return busy_reason();
  if (!last_attempt_) return "no trial recorded in this run yet";
  const int i = last_attempt_->trial;
  if (last_attempt_->frames <= 0)
    return state_.trials.at(static_cast<size_t>(i)).plan.name +
           " cannot be accepted: " + attempt_failure(*last_attempt_) + "; redo it (R)";
  try {
    if (state_.trials.at(static_cast<size_t>(i)).status == TrialStatus::kAccepted) return {};
    runner_->note(i, "accepted by the operator despite its verdict (" + last_attempt_->verdict() + ")");
    runner_->accept(i);
  } catch (const std::exception& e) {
    return e.what();
  }
  refresh_state();
  selected_ = -1;
  return {};
}

std::string RecordState::ask_accept() {
  accept_question_.clear();
  if (busy()) return busy_reason();
  if (!last_attempt_) return "no trial recorded in this run yet";
  const auto& trial = state_.trials.at(static_cast<size_t>(last_attempt_->trial));
  if (trial.status == TrialStatus::kAccepted) return {};
  if (last_attempt_->frames <= 0)
    return trial.plan.name + " cannot be accepted: " + attempt_failure(*last_attempt_) + "; redo it (R)";
  accept_question_ = trial.plan.name + " failed (" + attempt_failure(*last_attempt_) + "). Keep it anyway?";
  return {};
}

std::string RecordState::answer_accept(bool keep) {
  if (accept_question_.empty()) return "no question is open";
  if (!keep) {
    accept_question_.clear();
    return {};
  }
  return accept_last();
}

std::string RecordState::redo(int i) {
  if (busy()) return busy_reason();
  if (!has_session()) return "no session";
  if (i < 0) {
    // A recorded trial the operator picked in the list comes first: any trial can be redone.
    const bool picked_recorded = selected_ >= 0 && selected_ < static_cast<int>(state_.trials.size()) &&
                                 !state_.trials[static_cast<size_t>(selected_)].attempts.empty();
    if (picked_recorded)
      i = selected_;
    else if (last_attempt_)
      i = last_attempt_->trial;
    else
      return "no trial recorded in this run yet; pick a recorded trial in the list to redo it";
  }
  if (i >= static_cast<int>(state_.trials.size())) return "no such trial";
  if (state_.trials[static_cast<size_t>(i)].attempts.empty())
    return state_.trials[static_cast<size_t>(i)].plan.name + " has not been recorded yet";
  accept_question_.clear();
  try {
    runner_->redo(i);
  } catch (const std::exception& e) {
    return e.what();
  }
  refresh_state();
  selected_ = i;  // Start records it next
  // The notice described the folder as it was opened ("nothing is left to record"): no longer true.
  resume_notice_.clear();
  return {};
}

const Layout* RecordState::current_layout() const {
  const int i = recording() ? recording_trial_ : current_trial();
  if (!runner_ || i < 0) return nullptr;
  return &runner_->layout(i);
}

StatusReport RecordState::poll() {
  bool fresh = false;
  for (auto& s : job_.drain_reports()) {
    live_ = std::move(s);
    fresh = true;
  }
  if (fresh && live_) {
    const Layout* layout = current_layout();
    live_hands_ = layout ? ui::live_hands(live_->hub, *layout) : std::vector<LiveHand>{};
  }
  if (live_fusion_ && recording()) {
    live_fused_ = live_fusion_->latest();
    fusion_stats_ = live_fusion_->stats();
  }
  const JobState js = job_.state();
  if (job_handled_ || !job_finished(js) || !folder_) return {};
  job_handled_ = true;
  std::string line;
  bool bad = false;
  if (js == JobState::kFailed) {
    line = "Record: " + job_.error();
    bad = true;
  } else if (auto result = job_.result()) {
    if (result->preflight) {
      last_preflight_ = result->preflight;
      line = result->preflight->ok() ? "pre-flight passed for layout '" + result->preflight->layout_name + "'"
                                     : "pre-flight failed: " + result->preflight->failures().front();
      bad = bad || !result->preflight->ok();
    }
    if (result->calibration) {
      pending_calibration_ = result->calibration;
      const auto& c = *result->calibration;
      line = c.ok() ? c.trial_name + ": calibrated; read the residuals, then Apply or calibrate again"
                    : c.trial_name + ": " + c.failure;
      bad = bad || !c.ok();
    }
    if (result->attempt) {
      last_attempt_ = result->attempt;
      const auto& a = *result->attempt;
      const std::string& name = state_.trials.at(static_cast<size_t>(a.trial)).plan.name;
      line = name + ": " + a.verdict();
      if (a.quality && !a.quality->reasons.empty()) line += " — " + a.quality->reasons.front();
      // The CLI's rule: pass and warn are kept; a fail waits for the operator's redo or accept.
      if (a.verdict() != "fail") {
        try {
          runner_->accept(a.trial);
        } catch (const std::exception& e) {
          line += " (not accepted: " + std::string(e.what()) + ")";
          bad = true;
        }
        if (selected_ == a.trial) selected_ = -1;
      } else {
        selected_ = a.trial;
        bad = true;
      }
    }
  }
  recording_trial_ = -1;
  calibrating_ = false;
  live_.reset();
  live_hands_.clear();
  live_fused_.reset();
  live_fusion_.reset();  // the worker has detached it from the hub: joins its thread
  if (!pending_notes_.empty()) write_pending_notes();
  if (!last_note_error_.empty()) {
    line += (line.empty() ? "" : "; ") + std::exchange(last_note_error_, {});
    bad = true;
  }
  refresh_state();
  return {line, bad ? Severity::kError : Severity::kInfo};
}

}  // namespace lmc::ui
