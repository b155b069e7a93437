#include "ui/model/devices/calibration_step.h"

#include <algorithm>
#include <cctype>
#include <utility>

#include "core/common/number_format.h"
#include "core/io/layout_json.h"
#include "ui/scene/calibration_ghosts.h"

namespace lmc::ui {

const char* calibration_stage_name(CalibrationStage stage) {
  switch (stage) {
    case CalibrationStage::kIdle:
      return "idle";
    case CalibrationStage::kRecording:
      return "recording";
    case CalibrationStage::kCalibrating:
      return "calibrating";
    case CalibrationStage::kResult:
      return "result";
    case CalibrationStage::kApplied:
      return "applied";
  }
  return "?";
}

const char* calibration_residuals_explanation() {
  return "Residual: RMS distance (mm) of a controller's palm, wrist and knuckle points from the target (Vicon, or the "
         "other controllers) before > after. Disagreement: the same over all controllers. Moved mm / turned deg: the "
         "correction of the controller's origin and angle. About 2 mm remain between controllers after a good "
         "calibration; against Vicon 7-8 mm remain because markers sit on the skin while the controller reports joint "
         "centres.";
}

std::string CalibrationStep::record(const std::filesystem::path& dir, const CalibrationSettings& settings,
                                    double seconds) {
  if (busy()) return std::string("the Calibrate step is already ") + calibration_stage_name(stage_);
  if (!rig_.running()) return "start the controllers (or the simulated rig) first";
  const Layout layout = rig_.layout();  // what the trial records with: the workbench's layout and its serials
  if (std::string err = rig_.start_trial(dir, kTrialName, seconds); !err.empty()) return err;
  settings_ = settings;
  nominal_ = layout;
  seconds_ = seconds;
  outcome_.reset();
  stage_ = CalibrationStage::kRecording;
  cancelling_ = false;
  message_.clear();
  message_is_error_ = false;
  return {};
}

std::string CalibrationStep::calibrate_file(const std::filesystem::path& trial, const Layout& layout,
                                            const CalibrationSettings& settings) {
  if (busy()) return std::string("the Calibrate step is already ") + calibration_stage_name(stage_);
  if (trial.empty()) return "choose a recorded trial (an LMC recording file)";
  settings_ = settings;
  nominal_ = layout;
  outcome_.reset();
  message_.clear();
  message_is_error_ = false;
  start_job(trial);
  return {};
}

void CalibrationStep::start_job(const std::filesystem::path& trial) {
  TrialCalibrationRequest request;
  request.trial = trial;
  if (!settings_.vicon.empty()) request.vicon = settings_.vicon;
  request.anchor_to_layout = settings_.anchor_to_layout;
  job_.start(std::move(request), nominal_);
  stage_ = CalibrationStage::kCalibrating;
}

void CalibrationStep::cancel() {
  if (stage_ == CalibrationStage::kRecording) {
    // The engine ends the trial "interrupted" and keeps its rows; update() returns to idle once
    // the rig has reported it, so a new recording cannot collide with the ending one.
    cancelling_ = true;
    rig_.stop_trial();
  } else if (stage_ == CalibrationStage::kCalibrating) {
    job_.cancel();
    stage_ = CalibrationStage::kIdle;
    message_ = "calibration cancelled";
    message_is_error_ = false;
  }
}

void CalibrationStep::fail(std::string why) {
  stage_ = CalibrationStage::kIdle;
  message_ = std::move(why);
  message_is_error_ = true;
}

void CalibrationStep::update() {
  if (stage_ == CalibrationStage::kRecording) {
    if (rig_.recording()) return;
    const auto result = rig_.trial().result();
    if (cancelling_) {
      cancelling_ = false;
      stage_ = CalibrationStage::kIdle;
      message_ = "calibration recording cancelled" +
                 (result && result->recorded ? "; the partial trial stays in " + result->paths.recording.string()
                                             : std::string());
      message_is_error_ = false;
      return;
    }
    if (!result) return fail("the calibration trial failed: " + rig_.trial().error());
    if (result->outcome != devices::TrialOutcome::kCompleted || !result->recorded) {
      return fail("the calibration trial " + rig_.trial_name() + " " + devices::trial_outcome_name(result->outcome) +
                  (result->reason.empty() ? std::string() : ": " + result->reason));
    }
    start_job(result->paths.recording);
    return;
  }
  if (stage_ != CalibrationStage::kCalibrating || !job_finished(job_.state())) return;
  if (job_.state() == JobState::kFailed) return fail("calibration failed: " + job_.error());
  if (job_.state() != JobState::kCompleted || !job_.outcome()) return fail("calibration ended without a result");
  outcome_ = job_.outcome();
  stage_ = CalibrationStage::kResult;
  const auto warnings = outcome_->result.all_warnings();
  message_ = "calibrated from " + outcome_->trial +
             (warnings.empty() ? std::string(": no warnings") : ": " + std::to_string(warnings.size()) + " warning(s)");
  message_is_error_ = !warnings.empty();
}

double CalibrationStep::recording_fraction() const {
  if (stage_ != CalibrationStage::kRecording) return stage_ == CalibrationStage::kIdle ? 0.0 : 1.0;
  const auto& snap = rig_.trial().snapshot();
  if (!snap || seconds_ <= 0) return 0.0;
  return std::clamp(snap->recording_s / seconds_, 0.0, 1.0);
}

std::string CalibrationStep::activity() const {
  switch (stage_) {
    case CalibrationStage::kIdle:
      return {};
    case CalibrationStage::kRecording: {
      if (cancelling_) return "cancelling the recording...";
      const auto& snap = rig_.trial().snapshot();
      if (!snap || snap->phase == devices::TrialPhase::kWaitingForStreams)
        return "waiting for every controller to stream...";
      if (snap->phase != devices::TrialPhase::kRecording) return std::string(devices::trial_phase_name(snap->phase));
      return "hold the hand still and open: " + format_fixed(std::max(0.0, seconds_ - snap->recording_s), 1) +
             " s left";
    }
    case CalibrationStage::kCalibrating:
      return job_.stage().empty() ? "calibrating..." : job_.stage() + "...";
    case CalibrationStage::kResult:
      return "result ready: Apply, Save layout... or Discard";
    case CalibrationStage::kApplied:
      return "applied to the layout (Ctrl+Z undoes it)";
  }
  return {};
}

std::vector<CalibrationRow> calibration_rows(const CalibrationResult& result) {
  std::vector<CalibrationRow> out;
  for (const auto& d : result.devices) {
    CalibrationRow r;
    r.slot = d.slot;
    r.fitted = d.fitted;
    r.samples = d.all.samples;
    r.beyond_cut = d.beyond_cut;
    r.before_mm = d.all.before_mm;
    r.after_mm = d.all.after_mm;
    r.moved_mm = d.moved_mm;
    r.turned_deg = d.turned_deg;
    r.warnings = d.warnings;
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<CalibrationRow> CalibrationStep::rows() const {
  if (!outcome_) return {};
  return calibration_rows(outcome_->result);
}

std::vector<SceneItem> CalibrationStep::ghosts() const {
  if (stage_ != CalibrationStage::kResult || !outcome_) return {};
  return calibration_ghost_items(nominal_, outcome_->calibrated);
}

ActionResult CalibrationStep::apply(LayoutEditor* editor) {
  if (stage_ != CalibrationStage::kResult || !outcome_) return ActionResult::fail("no calibration result to apply");
  if (editor == nullptr) return ActionResult::fail("no layout document is open to apply the calibration to");
  ActionResult r = editor->apply_calibration(outcome_->calibrated);
  if (r) {
    stage_ = CalibrationStage::kApplied;
    message_ = "applied: the layout is now '" + outcome_->calibrated.name + "'";
    message_is_error_ = false;
  }
  return r;
}

bool CalibrationStep::undo_apply(LayoutEditor* editor) {
  if (stage_ != CalibrationStage::kApplied || editor == nullptr || !editor->can_undo()) return false;
  if (editor->undo_message() != "Apply calibration") return false;
  editor->undo();
  stage_ = CalibrationStage::kResult;
  message_ = "undid Apply calibration: the result waits again";
  message_is_error_ = false;
  return true;
}

void CalibrationStep::discard() {
  if (busy()) return;
  outcome_.reset();
  stage_ = CalibrationStage::kIdle;
  message_ = "calibration result discarded";
  message_is_error_ = false;
}

void CalibrationStep::notice_layout(const Layout& committed) {
  if (stage_ != CalibrationStage::kApplied || !outcome_) return;
  for (const auto& c : outcome_->calibrated.devices) {
    const int i = committed.find_slot(c.slot);
    if (i >= 0 && committed.devices[static_cast<size_t>(i)].pose == c.pose &&
        committed.devices[static_cast<size_t>(i)].offset_mm == c.offset_mm) {
      continue;
    }
    stage_ = CalibrationStage::kResult;
    message_ =
        "the layout no longer holds this calibration (undone or edited in the Layout tab): Apply again or Discard";
    message_is_error_ = false;
    return;
  }
}

std::string CalibrationStep::save(const std::filesystem::path& path) const {
  if (!outcome_) return "no calibration result to save";
  try {
    save_layout(outcome_->calibrated, path);
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

std::string CalibrationStep::suggested_file_name() const {
  std::string stem;
  for (const char c : nominal_.name) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_';
    if (keep)
      stem += c;
    else if (!stem.empty() && stem.back() != '-')
      stem += '-';
  }
  while (!stem.empty() && stem.back() == '-') stem.pop_back();
  return (stem.empty() ? std::string("layout") : stem) + "-calibrated.json";
}

}  // namespace lmc::ui
