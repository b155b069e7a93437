#include "ui/model/record/record_session_model.h"

#include <chrono>
#include <utility>

#include "ui/model/record/resume_notice.h"

namespace lmc::ui {

RecordSessionModel::RecordSessionModel() = default;

RecordSessionModel::~RecordSessionModel() {
  // The worker uses the runner and the folder: stop and join it before they go.
  job_.cancel_and_join();
}

std::string RecordSessionModel::adopt(session::SessionFolder folder, const RecordSettings& settings, bool resumed) {
  folder_ = std::make_unique<session::SessionFolder>(std::move(folder));
  try {
    devices::SessionRunOptions options;
    options.backend = settings.backend;
    options.fast = settings.fast;
    options.sim = settings.sim;
    options.countdown_s = settings.countdown_s;
    runner_ = std::make_unique<devices::SessionRunner>(*folder_, options);
  } catch (const std::exception& e) {
    folder_.reset();  // releases the folder's lock
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

std::string RecordSessionModel::create(const std::filesystem::path& dir, const session::NewSessionSpec& spec,
                                       const RecordSettings& settings) {
  if (busy()) return "a trial or pre-flight is running; stop it first";
  close();
  try {
    return adopt(session::SessionFolder::create(dir, spec), settings, false);
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string RecordSessionModel::open(const std::filesystem::path& dir, const RecordSettings& settings) {
  if (busy()) return "a trial or pre-flight is running; stop it first";
  close();
  try {
    return adopt(session::SessionFolder::open(dir), settings, true);
  } catch (const std::exception& e) {
    return e.what();
  }
}

void RecordSessionModel::close() {
  job_.cancel_and_join();
  runner_.reset();
  folder_.reset();
  state_ = {};
  recovered_.clear();
  resume_notice_.clear();
  recording_trial_ = -1;
  selected_ = -1;
}

void RecordSessionModel::refresh_state() {
  if (folder_) state_ = folder_->state();
}

int RecordSessionModel::current_trial() const {
  if (!has_session()) return -1;
  if (selected_ >= 0 && selected_ < static_cast<int>(state_.trials.size())) return selected_;
  return state_.next_trial();
}

void RecordSessionModel::select(int i) {
  selected_ = (has_session() && i >= 0 && i < static_cast<int>(state_.trials.size())) ? i : -1;
}

const session::TrialType& RecordSessionModel::trial_type(int i) const {
  const auto& plan = state_.trials.at(static_cast<size_t>(i)).plan;
  return state_.protocol.trial_types.at(static_cast<size_t>(plan.trial_type));
}

std::string RecordSessionModel::block_instructions() const {
  const int i = current_trial();
  if (!runner_ || i < 0) return {};
  return runner_->block_instructions(i);
}

bool RecordSessionModel::needs_preflight() const {
  const int i = current_trial();
  // runner_ is read, not changed; while the worker runs the answer is not needed.
  return runner_ && i >= 0 && !busy() && runner_->needs_preflight(i);
}

std::string RecordSessionModel::start_preflight() {
  if (!has_session()) return "open or create a session first";
  if (busy()) return "a trial or pre-flight is running";
  const int i = current_trial();
  if (i < 0) return "every trial is accepted";
  devices::SessionRunner* runner = runner_.get();
  recording_trial_ = -1;
  job_handled_ = false;
  job_.start([runner, i](std::stop_token stop, JobChannel<devices::TrialSnapshot>&) {
    RecordWorkResult r;
    r.preflight = runner->preflight(i, stop);
    return r;
  });
  return {};
}

std::string RecordSessionModel::override_preflight(const std::string& reason) {
  if (busy()) return "a trial or pre-flight is running";
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

std::string RecordSessionModel::start_trial() {
  if (!has_session()) return "open or create a session first";
  if (busy()) return "a trial or pre-flight is running";
  const int i = current_trial();
  if (i < 0) return "every trial is accepted";
  if (state_.trials[static_cast<size_t>(i)].status == session::TrialStatus::kAccepted)
    return state_.trials[static_cast<size_t>(i)].plan.name + " is accepted; redo it (R) to record it again";
  if (runner_->needs_preflight(i)) return "run the pre-flight for this layout first (or override it with a reason)";
  devices::SessionRunner* runner = runner_.get();
  recording_trial_ = i;
  live_.reset();
  // Shown as recording at once; the folder's own state says so when the worker is done.
  state_.trials[static_cast<size_t>(i)].status = session::TrialStatus::kRecording;
  job_handled_ = false;
  job_.start([runner, i](std::stop_token stop, JobChannel<devices::TrialSnapshot>& channel) {
    RecordWorkResult r;
    r.attempt = runner->run_trial(i, stop, [&channel](const devices::TrialSnapshot& s) { channel.report(s); });
    return r;
  });
  return {};
}

void RecordSessionModel::stop_trial() {
  if (recording()) job_.cancel();
}

std::string RecordSessionModel::accept_last() {
  if (busy()) return "a trial is running";
  if (!last_attempt_) return "no trial recorded in this run yet";
  const int i = last_attempt_->trial;
  try {
    if (state_.trials.at(static_cast<size_t>(i)).status == session::TrialStatus::kAccepted) return {};
    runner_->note(i, "accepted by the operator despite its verdict (" + last_attempt_->verdict() + ")");
    runner_->accept(i);
  } catch (const std::exception& e) {
    return e.what();
  }
  refresh_state();
  selected_ = -1;
  return {};
}

std::string RecordSessionModel::redo(int i) {
  if (busy()) return "a trial is running";
  if (!has_session()) return "no session";
  if (i < 0) {
    if (!last_attempt_) return "no trial recorded in this run yet";
    i = last_attempt_->trial;
  }
  if (i >= static_cast<int>(state_.trials.size())) return "no such trial";
  if (state_.trials[static_cast<size_t>(i)].attempts.empty()) return state_.trials[static_cast<size_t>(i)].plan.name + " has not been recorded yet";
  try {
    runner_->redo(i);
  } catch (const std::exception& e) {
    return e.what();
  }
  refresh_state();
  selected_ = i;  // Start records it next
  return {};
}

// Feeds each controller's newest frame from the engine's status snapshot into the causal fusion.
// Snapshots come about ten times a second, so this is the fused hand as the operator sees it,
// not every frame (a per-frame fusion on its own thread is the next step, issue #11).
void RecordSessionModel::fuse_snapshot(const devices::HubSnapshot& hub) {
  const Layout* layout = current_layout();
  if (!layout) return;
  if (!fusion_) {
    fusion_ = std::make_unique<OnlineFusion>(*layout);
    fused_frame_ids_.assign(static_cast<size_t>(layout->device_count()), -1);
  }
  const auto t0 = std::chrono::steady_clock::now();
  bool added = false;
  for (const auto& d : hub.devices) {
    if (d.slot_index < 0 || d.slot_index >= layout->device_count() || !d.latest || !d.connected) continue;
    auto& last = fused_frame_ids_[static_cast<size_t>(d.slot_index)];
    if (d.latest->frame_id == last) continue;
    last = d.latest->frame_id;
    try {
      fusion_->add(*d.latest, d.slot_index, static_cast<double>(d.latest->timestamp_us) * 1e-6);
      added = true;
    } catch (const std::exception&) {
      // A frame the fusion refuses (non-finite time) is left out of the live view only; the
      // recording keeps it and the verdict judges it.
    }
  }
  if (!added) return;
  live_fused_ = fusion_->current();
  fusion_step_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

const Layout* RecordSessionModel::current_layout() const {
  const int i = recording() ? recording_trial_ : current_trial();
  if (!runner_ || i < 0) return nullptr;
  return &runner_->layout(i);
}

std::string RecordSessionModel::poll() {
  bool fresh = false;
  for (auto& s : job_.drain_reports()) {
    live_ = std::move(s);
    fresh = true;
  }
  if (fresh && live_) {
    const Layout* layout = current_layout();
    live_hands_ = layout ? ui::live_hands(live_->hub, *layout) : std::vector<LiveHand>{};
    fuse_snapshot(live_->hub);
  }
  const JobState js = job_.state();
  if (job_handled_ || !job_finished(js) || !folder_) return {};
  job_handled_ = true;
  std::string line;
  if (js == JobState::kFailed) {
    line = "Record: " + job_.error();
  } else if (auto result = job_.result()) {
    if (result->preflight) {
      last_preflight_ = result->preflight;
      line = result->preflight->ok() ? "pre-flight passed for layout '" + result->preflight->layout_name + "'"
                                     : "pre-flight failed: " + result->preflight->failures().front();
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
        }
        if (selected_ == a.trial) selected_ = -1;
      } else {
        selected_ = a.trial;
      }
    }
  }
  recording_trial_ = -1;
  live_.reset();
  live_hands_.clear();
  live_fused_.reset();
  fusion_.reset();
  refresh_state();
  return line;
}

}  // namespace lmc::ui
