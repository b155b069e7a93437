#include "devices/session_runner/session_runner.h"

#include <cmath>
#include <sstream>

#include "core/calibration/calibrated_layout.h"
#include "core/calibration/calibration_summary.h"
#include "core/common/error.h"
#include "core/io/json_checked.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/recorder_sidecar.h"
#include "core/session/trial_files.h"
#include "devices/device_hub.h"
#include "devices/record/recorder.h"
#include "devices/session_runner/stream_probe.h"
#include "devices/source_factory.h"
#include "devices/vicon/vicon_trigger.h"

namespace fs = std::filesystem;

namespace lmc::devices {

struct SessionRunner::RecordingHub {
  std::unique_ptr<DeviceHub> hub;
  DeviceHub* hub_ref = nullptr;  // a hub owned elsewhere (the caller's, or the block's hardware hub)
  SimSource* sim = nullptr;
  DeviceHub& get() const { return hub ? *hub : *hub_ref; }
};

namespace {

// Frames carry the hub's slot numbers; the session reads them by its own layout's slots.
std::string slots_differ(const Layout& hub_layout, const Layout& session_layout) {
  std::vector<std::string> a, b;
  for (const auto& d : hub_layout.devices) a.push_back(d.slot);
  for (const auto& d : session_layout.devices) b.push_back(d.slot);
  if (a == b) return {};
  auto join = [](const std::vector<std::string>& v) {
    std::string out;
    for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
    return out;
  };
  return "the running controllers' layout '" + hub_layout.name + "' has slots " + join(a) + "; the session's layout '" +
         session_layout.name + "' has " + join(b) + ": open a layout with the session's slots in the Layout tab";
}

}  // namespace

std::string before_go_reason(const std::string& outcome) {
  return (outcome == "aborted" ? std::string("aborted") : std::string("stopped")) + " before go — no data";
}

std::string AttemptResult::verdict() const {
  return quality ? quality->verdict : std::string("fail");
}

SessionRunner::SessionRunner(SessionFolder& folder, SessionRunOptions options)
    : folder_(folder), options_(std::move(options)) {
  const auto& state = folder_.state();
  protocol_ = state.protocol;
  for (const auto& t : state.trials) plan_.push_back(t.plan);
  for (const auto& [key, json] : state.setup.layouts)
    layouts_[key] = layout_from_json(json, (folder_.dir() / "session.json").string() + "#/layouts/" + key);
  const SourceSpec spec = parse_source_spec(options_.backend);
  if (options_.fast && spec.backend == "leapc") throw Error("--fast applies to the simulated rig and replays only");
  // The simulated subject has the real subject's hand size when the manifest knows it.
  if (state.subject().hand_length_mm) options_.sim.hand_length_mm = *state.subject().hand_length_mm;
  if (state.subject().hand_breadth_mm) options_.sim.hand_breadth_mm = *state.subject().hand_breadth_mm;
}

SessionRunner::~SessionRunner() = default;

const Layout& SessionRunner::layout_for(int i) const {
  const std::string& key = plan_.at(static_cast<size_t>(i)).layout_key;
  auto it = layouts_.find(key);
  if (it == layouts_.end()) throw Error("the session's manifest has no layout for block '" + key + "'");
  return it->second;
}

Layout SessionRunner::nominal_layout_for(int i) const {
  const std::string& key = plan_.at(static_cast<size_t>(i)).layout_key;
  const auto& nominal = folder_.state().nominal_layouts;
  if (auto it = nominal.find(key); it != nominal.end())
    return layout_from_json(it->second, (folder_.dir() / "session.json").string() + "#/nominal_layouts/" + key);
  return layout_for(i);
}

bool SessionRunner::needs_preflight(int i) const {
  return !cleared_blocks_.contains(plan_.at(static_cast<size_t>(i)).layout_key);
}

std::unique_ptr<SessionRunner::RecordingHub> SessionRunner::make_recording_hub(int i, double duration_s,
                                                                               std::uint64_t seed,
                                                                               const std::string& motion) const {
  const SourceSpec spec = parse_source_spec(options_.backend);
  const PlannedTrial& p = plan_.at(static_cast<size_t>(i));
  SourceSettings settings;
  // The controllers stand where the block's layout was set up; a calibration changes what the
  // session believes about them, not where they are (the simulator's truth stays put).
  settings.layout = nominal_layout_for(i);
  settings.sim = options_.sim;
  settings.sim.seed = seed;
  // One placement error for the whole session (sim_config.h): the controllers do not move between trials.
  settings.sim.calibration_seed = options_.sim.calibration_seed.value_or(options_.sim.seed);
  apply_motion_spec(settings.sim, motion.empty() ? p.sim_motion : motion);
  settings.speed = options_.fast ? 0.0 : 1.0;
  settings.duration_s = spec.backend == "sim" ? duration_s : 0.0;
  HubOptions hub_options;
  hub_options.backpressure = options_.fast;
  auto recording = std::make_unique<RecordingHub>();
  recording->hub = std::make_unique<DeviceHub>(settings.layout, hub_options);
  std::unique_ptr<FrameSource> source = make_source(spec, settings);
  recording->sim = dynamic_cast<SimSource*>(source.get());
  recording->hub->add_source(std::move(source));
  return recording;
}

std::unique_ptr<SessionRunner::RecordingHub> SessionRunner::hub_for_recording(int i, double duration_s,
                                                                              std::uint64_t seed,
                                                                              const std::string& motion) const {
  if (options_.external_hub != nullptr) {
    auto recording = std::make_unique<RecordingHub>();
    recording->hub_ref = options_.external_hub;
    return recording;
  }
  if (hardware_hub_ && hardware_block_ == plan_.at(static_cast<size_t>(i)).layout_key) {
    // Borrows the block's hub, which stays up for its next trials.
    auto recording = std::make_unique<RecordingHub>();
    recording->hub_ref = hardware_hub_->hub.get();
    recording->sim = hardware_hub_->sim;
    return recording;
  }
  return make_recording_hub(i, duration_s, seed, motion);
}

std::uint64_t SessionRunner::bytes_still_needed(int from) const {
  std::uint64_t bytes = 0;
  const auto& trials = folder_.state().trials;
  for (size_t k = static_cast<size_t>(std::max(from, 0)); k < plan_.size(); ++k) {
    if (trials[k].status == TrialStatus::kAccepted) continue;
    const TrialType& type = protocol_.trial_types.at(static_cast<size_t>(plan_[k].trial_type));
    bytes += estimated_trial_bytes(layout_for(static_cast<int>(k)).device_count(), type.duration_s);
  }
  return bytes;
}

PreflightReport SessionRunner::preflight(int i, std::stop_token stop) {
  const PlannedTrial& p = plan_.at(static_cast<size_t>(i));
  PreflightInputs in;
  in.block = p.layout_key;
  in.layout = layout_for(i);
  in.folder = folder_.dir();
  in.bytes_needed = bytes_still_needed(i);
  in.min_rate_hz = protocol_.trial_types.at(static_cast<size_t>(p.trial_type)).quality.fail_min_rate_hz;
  in.vicon_target = vicon_target();
  // The probe listens to the controllers for a moment: a hub of its own for the simulator and
  // replays (their recordings' hubs are made per trial), the block's hub for real controllers.
  std::unique_ptr<RecordingHub> probe_hub;
  DeviceHub* hub = nullptr;
  try {
    if (options_.external_hub != nullptr) {
      if (auto why = slots_differ(options_.external_hub->layout(), in.layout); !why.empty()) throw Error(why);
      hub = options_.external_hub;
    } else if (parse_source_spec(options_.backend).backend == "leapc") {
      if (hardware_block_ != p.layout_key) {
        hardware_hub_.reset();
        hardware_hub_ = make_recording_hub(i, 0, options_.sim.seed);
        hardware_hub_->hub->start();
        hardware_block_ = p.layout_key;
      }
      hub = hardware_hub_->hub.get();
    } else {
      probe_hub = make_recording_hub(i, 2.0, options_.sim.seed);
      hub = probe_hub->hub.get();  // started by probe_streams, once it listens
    }
    const auto timeout = std::chrono::milliseconds(static_cast<int>(options_.preflight_timeout_s * 1000));
    in.slots = probe_streams(*hub, timeout, 20, stop);
  } catch (const std::exception& e) {
    PreflightReport r;
    r.block = p.layout_key;
    r.layout_name = in.layout.name;
    r.items.push_back(
        {"controllers", false, std::string("cannot start the ") + options_.backend + " backend: " + e.what()});
    folder_.preflight(r.block, false, preflight_to_json(r));
    return r;
  }
  if (probe_hub) probe_hub->hub->stop();
  PreflightReport report = evaluate_preflight(in);
  folder_.preflight(report.block, report.ok(), preflight_to_json(report));
  if (report.ok()) cleared_blocks_.insert(p.layout_key);
  return report;
}

void SessionRunner::override_preflight(int i, const std::string& reason) {
  const std::string& block = plan_.at(static_cast<size_t>(i)).layout_key;
  folder_.preflight_override(block, reason);
  cleared_blocks_.insert(block);
}

namespace {

// Keeps a tap on a hub for one scope, whatever ends it.
class TapAttachment {
 public:
  TapAttachment(DeviceHub& hub, FrameTap* tap) : hub_(hub), tap_(tap) { hub_.add_tap(tap_); }
  ~TapAttachment() { hub_.remove_tap(tap_); }
  TapAttachment(const TapAttachment&) = delete;
  TapAttachment& operator=(const TapAttachment&) = delete;

 private:
  DeviceHub& hub_;
  FrameTap* tap_;
};

// A fail verdict with its one reason (nothing to judge, or nothing that could be read).
QualityReport fail_verdict(std::string reason) {
  QualityReport q;
  q.verdict = "fail";
  q.reasons.push_back(std::move(reason));
  return q;
}

// The verdict of a recorded attempt from its files, as processing will read them.
QualityReport assess_recorded_attempt(const TrialFiles& paths, const TrialType& type, const Layout& layout,
                                      bool vicon_expected, const std::optional<fs::path>& vicon_export_dir) {
  const LmcRecording recording = read_lmc_recording(paths.recording);
  const RecorderSidecar sidecar = read_recorder_sidecar(paths.sidecar);
  QualityInputs in;
  in.recording = &recording;
  in.sidecar = &sidecar;
  in.layout = layout;
  in.planned_s = type.duration_s;
  in.thresholds = type.quality;
  in.rom = type.rom;
  in.vicon_expected = vicon_expected;
  in.vicon_export_dir = vicon_export_dir;
  return assess_trial(in);
}

// An attempt that did not complete is a recording fault whatever its data look like.
void fail_incomplete_attempt(AttemptResult& result) {
  if (result.outcome == "completed" || result.quality->verdict == "fail") return;
  result.quality->reasons.insert(result.quality->reasons.begin(), "the trial " + result.outcome + ": " + result.reason);
  result.quality->verdict = "fail";
}

}  // namespace

AttemptResult SessionRunner::run_trial(int i, std::stop_token stop,
                                       const std::function<void(const TrialSnapshot&)>& on_status, FrameTap* live_tap,
                                       const std::function<std::string()>& abort_reason) {
  const PlannedTrial& p = plan_.at(static_cast<size_t>(i));
  const TrialType& type = protocol_.trial_types.at(static_cast<size_t>(p.trial_type));
  const auto& trial_state = folder_.state().trials.at(static_cast<size_t>(i));
  if (trial_state.status == TrialStatus::kAccepted)
    throw Error("trial " + p.name + " is accepted; redo it first to record it again");
  // Files of an earlier attempt still under the trial's name go under superseded/ first:
  // nothing recorded is ever overwritten.
  if (!trial_state.attempts.empty() && trial_state.attempts.back().superseded_dir.empty()) folder_.redo(i);

  AttemptResult result;
  result.trial = i;
  // Journal first: if this process dies from here on, the next run finds the trial interrupted.
  result.attempt = folder_.trial_started(i);

  TrialEngineConfig config = engine_config(p.name, type.duration_s, type.operator_cue, result.attempt, p.layout_key);
  // A calibrated block's trials carry the calibrated layout in their sidecars, so processing
  // realigns them with it (the hub keeps the layout the controllers were set up by).
  if (folder_.state().nominal_layouts.contains(p.layout_key)) config.sidecar_layout = layout_for(i);

  TrialResult tr;
  try {
    const std::uint64_t seed = options_.sim.seed + 7919ULL * static_cast<std::uint64_t>(i) +
                               104729ULL * static_cast<std::uint64_t>(result.attempt - 1);
    const std::unique_ptr<RecordingHub> recording = hub_for_recording(i, type.duration_s, seed);
    if (recording->sim != nullptr) config.extra["simulator"] = sim_config_to_json(options_.sim);
    TapAttachment tap(recording->get(), live_tap);
    TrialEngine engine(recording->get(), recording->sim, config);
    tr = engine.run(stop, on_status);
  } catch (const std::exception& e) {
    tr.outcome = TrialOutcome::kFailed;
    tr.reason = e.what();
  }
  // Interrupted means the stop token: the operator's Space or Esc, or the program closing.
  const bool by_operator = tr.outcome == TrialOutcome::kInterrupted;
  if (tr.outcome == TrialOutcome::kInterrupted && abort_reason) {
    if (std::string why = abort_reason(); !why.empty()) {
      tr.outcome = TrialOutcome::kAborted;
      tr.reason = std::move(why);
    }
  }
  result.outcome = trial_outcome_name(tr.outcome);
  result.reason = tr.reason;
  result.frames = tr.recorder.frames_written;
  result.reached_go = !tr.go_utc.empty();
  folder_.trial_stopped(i, result.outcome, result.reason, tr.go_utc);

  // The verdict, seconds after the trial: the same recording and sidecar processing will read.
  const TrialFiles paths = trial_files(folder_.dir(), p.name);
  // Stopped before go: the countdown is never recorded, so there is nothing to judge and the
  // controllers are not at fault; assessing the empty file would blame each of them.
  const bool stopped_before_go = by_operator && !result.reached_go;
  try {
    if (stopped_before_go) {
      result.quality = fail_verdict(before_go_reason(result.outcome));
      result.quality->planned_s = type.duration_s;
    } else if (fs::exists(paths.recording) && fs::exists(paths.sidecar)) {
      result.quality =
          assess_recorded_attempt(paths, type, layout_for(i), config.vicon.has_value(), options_.vicon_export_dir);
    }
  } catch (const std::exception& e) {
    result.quality = fail_verdict(std::string("the recording cannot be read back: ") + e.what());
  }
  if (!result.quality) {
    result.quality =
        fail_verdict("nothing was recorded: " + (result.reason.empty() ? std::string("no file") : result.reason));
  }
  fail_incomplete_attempt(result);
  folder_.trial_verdict(i, quality_to_json(*result.quality));
  return result;
}

TrialEngineConfig SessionRunner::engine_config(const std::string& name, double seconds, const std::string& operator_cue,
                                               int attempt, const std::string& block) const {
  TrialEngineConfig config;
  config.output_dir = folder_.dir();
  config.trial = name;
  config.seconds = seconds;
  config.countdown_s = options_.fast ? 0.0 : options_.countdown_s;
  config.stream_timeout_s = options_.stream_timeout_s;
  if (auto target = vicon_target()) {
    ViconTriggerConfig vc = parse_vicon_target(*target);
    const auto& vicon = folder_.state().setup.vicon;
    if (vicon.contains("database_path")) vc.database_path = vicon["database_path"].get<std::string>();
    vc.description = operator_cue;
    config.vicon = vc;
  }
  config.backend = parse_source_spec(options_.backend).backend;
  config.extra["session"] = {{"subject", folder_.state().subject().subject_id},
                             {"attempt", attempt},
                             {"protocol", protocol_.name},
                             {"block", block}};
  return config;
}

std::optional<std::string> SessionRunner::vicon_target() const {
  const auto& vicon = folder_.state().setup.vicon;
  if (!vicon.is_object() || !vicon.contains("host")) return std::nullopt;
  std::string target = vicon["host"].get<std::string>();
  if (vicon.contains("port")) target += ":" + std::to_string(vicon["port"].get<int>());
  return target;
}

void SessionRunner::accept(int i) {
  folder_.trial_accepted(i);
}

void SessionRunner::redo(int i) {
  folder_.redo(i);
}

void SessionRunner::note(int i, const std::string& text) {
  folder_.note(i, text);
}

bool SessionRunner::needs_calibration(int i) const {
  if (!protocol_.calibration) return false;
  const auto& cal = folder_.state().calibration;
  const auto it = cal.find(plan_.at(static_cast<size_t>(i)).layout_key);
  return it == cal.end() || !it->second.done();
}

BlockCalibration SessionRunner::calibrate_block(int i, std::stop_token stop,
                                                const std::function<void(const TrialSnapshot&)>& on_status) {
  if (!protocol_.calibration) throw Error("the session's protocol has no calibration step");
  const PlannedTrial& p = plan_.at(static_cast<size_t>(i));
  const CalibrationStep& step = *protocol_.calibration;
  BlockCalibration out;
  out.trial = i;
  out.block = p.layout_key;
  // Journal first: a process that dies from here on leaves the step "recording", done again on resume.
  out.attempt = folder_.calibration_started(p.layout_key);
  out.trial_name = calibration_trial_name(p.layout_key, out.attempt);
  // The block's layout as created: a second calibration starts from it, not from the first's result.
  const Layout nominal = nominal_layout_for(i);

  TrialEngineConfig config =
      engine_config(out.trial_name, step.duration_s, step.operator_cue, out.attempt, p.layout_key);
  config.extra["session"]["calibration"] = true;
  TrialResult tr;
  try {
    // The simulated subject holds the trial's palm pose still (the step's cue).
    const std::unique_ptr<RecordingHub> recording =
        hub_for_recording(i, step.duration_s, options_.sim.seed + 31ULL * static_cast<std::uint64_t>(out.attempt),
                          protocol_.poses.at(static_cast<size_t>(p.pose)).key + "/static");
    if (recording->sim != nullptr) config.extra["simulator"] = sim_config_to_json(options_.sim);
    TrialEngine engine(recording->get(), recording->sim, config);
    tr = engine.run(stop, on_status);
  } catch (const std::exception& e) {
    tr.outcome = TrialOutcome::kFailed;
    tr.reason = e.what();
  }
  if (tr.outcome != TrialOutcome::kCompleted) {
    out.failure = "the calibration trial " + std::string(trial_outcome_name(tr.outcome)) +
                  (tr.reason.empty() ? std::string() : ": " + tr.reason);
    return out;
  }
  try {
    TrialCalibrationRequest request;
    const TrialFiles files = trial_files(folder_.dir(), out.trial_name);
    request.trial = files.recording;
    // The trial's Vicon file: where Vicon exports, else beside the recording (where the simulator
    // writes its truth and where a lab may copy the export).
    for (const fs::path& dir : {options_.vicon_export_dir.value_or(fs::path()), folder_.dir()}) {
      if (dir.empty() || request.vicon) continue;
      if (const fs::path trc = dir / (out.trial_name + ".trc"); fs::exists(trc)) request.vicon = trc;
    }
    out.fit = calibrate_trial(request, nominal);
    out.summary = calibration_summary_json(out.fit->result);
    out.residual_table = residual_table(out.fit->result);
    out.warnings = out.fit->result.all_warnings();
    for (const auto& w : out.fit->file_warnings) out.warnings.push_back(w);
  } catch (const std::exception& e) {
    out.fit.reset();
    out.failure = std::string("the calibration trial cannot be calibrated: ") + e.what();
  }
  return out;
}

void SessionRunner::apply_calibration(const BlockCalibration& c) {
  if (!c.ok()) throw Error("block " + c.block + " has no calibration to apply: " + c.failure);
  folder_.calibration_applied(c.block, c.attempt, layout_to_json(c.fit->calibrated), c.summary);
  layouts_[c.block] = c.fit->calibrated;
  // The controllers moved on paper: the block's pre-flight still holds (same rig, same slots).
}

void SessionRunner::keep_nominal_layout(int i, const std::string& reason, const BlockCalibration* c) {
  const std::string& block = plan_.at(static_cast<size_t>(i)).layout_key;
  folder_.calibration_kept_nominal(block, reason, c != nullptr ? c->summary : nlohmann::json(nullptr));
  const auto& layouts = folder_.state().setup.layouts;
  layouts_[block] =
      layout_from_json(layouts.at(block), (folder_.dir() / "session.json").string() + "#/layouts/" + block);
}

std::string SessionRunner::block_instructions(int i) const {
  const Layout& layout = layout_for(i);
  const PlannedTrial& p = plan_.at(static_cast<size_t>(i));
  std::ostringstream s;
  s << "Set up layout '" << layout.name << "' (block " << p.layout_key << "):";
  s.setf(std::ios::fixed);
  s.precision(0);
  for (const auto& d : layout.devices) {
    const DevicePose& pose = d.pose;
    s << "\n  " << d.slot;
    if (d.serial) s << " (" << *d.serial << ")";
    s << " at x " << pose.x_mm << " mm, z " << pose.z_mm << " mm, tilt rx " << pose.rx_deg << "°, turn ry "
      << pose.ry_deg << "°";
  }
  return s.str();
}

}  // namespace lmc::devices
