#pragma once
// The Devices tab's Calibrate step without ImGui, so tests drive it directly:
//
//   idle ─record()──────────▶ recording ─trial ends─▶ calibrating ─job ends─▶ result ─apply()─▶ applied
//   idle ─calibrate_file()──────────────────────────▶ calibrating              result ─discard()─▶ idle
//   recording / calibrating ─cancel()─▶ idle          applied ─undo_apply() or notice_layout()─▶ result
//
// The 5 s still-hand trial is the rig's own test recording (LiveRig::start_trial, the one
// TrialEngine on a worker): this class never opens a device. Calibration runs on a worker
// (CalibrationJob, the same sequence as `lmc calibrate`). Apply goes through the layout
// document's owner (LayoutEditor) as one undo step; Save writes the calibrated layout, whose name
// and description already say what it is (core/calibration/calibrated_layout.h). UI thread only.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/layout/layout.h"
#include "ui/model/devices/calibration_job.h"
#include "ui/model/devices/live_rig.h"
#include "ui/model/layout_editor.h"
#include "ui/scene/scene_items.h"

namespace lmc::ui {

enum class CalibrationStage { kIdle, kRecording, kCalibrating, kResult, kApplied };
const char* calibration_stage_name(CalibrationStage stage);  // "idle", "recording", …

struct CalibrationSettings {
  std::filesystem::path vicon;    // empty: calibrate the controllers against each other
  bool anchor_to_layout = false;  // with Vicon: keep the layout's world frame (lmc calibrate --anchor-to-layout)
};

// One controller's line of the results table.
struct CalibrationRow {
  std::string slot;
  bool fitted = false;
  int samples = 0;
  int beyond_cut = 0;  // of them, with a coordinate clamped at the axis cut: used through their other ones
  double before_mm = 0, after_mm = 0;  // RMS over all its points (NaN without samples)
  double moved_mm = 0, turned_deg = 0;
  std::vector<std::string> warnings;
};

// The table's lines for a calibration result (the Devices tab's step and the Record tab's block
// calibration show the same table).
std::vector<CalibrationRow> calibration_rows(const CalibrationResult& result);

// How to read the residuals, in the README's words ("Calibrating controllers").
const char* calibration_residuals_explanation();

class CalibrationStep {
 public:
  static constexpr double kTrialSeconds = 5.0;
  static constexpr const char* kTrialName = "Calibration";

  explicit CalibrationStep(LiveRig& rig) : rig_(rig) {}

  // Records a still hand for `seconds` into `dir` through the rig, then calibrates that trial
  // with the rig's layout. Returns the reason when it cannot start (empty when it started).
  std::string record(const std::filesystem::path& dir, const CalibrationSettings& settings,
                     double seconds = kTrialSeconds);
  // Calibrates a trial recorded earlier with `layout` (e.g. a shared real trial).
  std::string calibrate_file(const std::filesystem::path& trial, const Layout& layout,
                             const CalibrationSettings& settings);
  // Stops the recording (its rows stay on disk) or drops the running calibration; back to idle.
  void cancel();
  // Once a frame, after the rig's poll(): moves on when the trial or the calibration ended.
  void update();

  CalibrationStage stage() const { return stage_; }
  bool busy() const { return stage_ == CalibrationStage::kRecording || stage_ == CalibrationStage::kCalibrating; }
  // Share of the recording done (0…1) while recording; what is happening now, in words.
  double recording_fraction() const;
  std::string activity() const;
  // What went wrong last (a trial that failed, a calibration that threw), or why it went back to idle.
  const std::string& message() const { return message_; }
  bool message_is_error() const { return message_is_error_; }

  // The result (kResult, kApplied); null otherwise.
  std::shared_ptr<const CalibrationOutcome> outcome() const { return outcome_; }
  // The layout the trial was recorded with (the "before" of the comparison).
  const Layout& nominal() const { return nominal_; }
  std::vector<CalibrationRow> rows() const;
  // The 3D view's comparison while a result waits for Apply or Discard (calibration_ghosts.h);
  // empty in every other stage.
  std::vector<SceneItem> ghosts() const;

  // Applies the result through `editor` (null: no layout document open) as one undo step.
  ActionResult apply(LayoutEditor* editor);
  // Ctrl+Z after Apply: undoes the "Apply calibration" step and shows the result again. False
  // when the editor's last step is something else (nothing is undone then).
  bool undo_apply(LayoutEditor* editor);
  void discard();
  // Once a frame with the document's committed layout: when it no longer holds the applied
  // corrections (undone in the Layout tab, or a controller moved since), the result waits again.
  void notice_layout(const Layout& committed);
  // Writes the calibrated layout (atomic, core/io/layout_json.h); error text or empty.
  std::string save(const std::filesystem::path& path) const;
  // "paper-initial-calibrated.json"
  std::string suggested_file_name() const;

 private:
  void start_job(const std::filesystem::path& trial);
  void fail(std::string why);

  LiveRig& rig_;
  CalibrationJob job_;
  CalibrationStage stage_ = CalibrationStage::kIdle;
  CalibrationSettings settings_;
  Layout nominal_;
  double seconds_ = kTrialSeconds;
  bool cancelling_ = false;
  std::shared_ptr<const CalibrationOutcome> outcome_;
  std::string message_;
  bool message_is_error_ = false;
};

}  // namespace lmc::ui
