// The Record tab's pictures: a quick session on the simulated rig in real time (no countdown),
// its first trial recorded to its verdict; record.png and record-trial.png 1.5 s into the second
// (the trial list with a verdict, the cue, the red circle, the controller strips, the fused hand),
// the subject screen at that moment, the verdict once the trial ends; then the session opened
// again to redo its last trial (the resume notice and the pre-flight), a protocol that calibrates
// each block (the residual table), and a filled-in set-up form.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "ui/app/capture/capture_scratch.h"
#include "ui/app/capture/tab_capture.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/record/record_tab.h"

namespace lmc::ui {
namespace {

class RecordCapture final : public TabCapture {
 public:
  RecordCapture(RecordTab& tab, WorkbenchContext& context)
      : tab_(tab), model_(tab.model()), subject_(context.subject_screen()) {}

  int prepare() override {
    driving_ = true;
    stage_ = "record";
    subject_.open = true;  // rendered hidden beside the main window from now on
    return 4;
  }

  std::vector<std::string> extra_captures() const override {
    return {"record-trial", "subject-screen", "record-verdict", "record-resume", "record-calibration", "record-setup"};
  }

  void prepare_extra(const std::string& name) override {
    stage_ = name;
    if (name == "record-resume") reopen_to_redo_last_trial();
    if (name == "record-calibration") calibrated_protocol();
    if (name == "record-setup") filled_in_form();
  }

  bool busy() const override {
    if (!driving_) return false;
    const bool mid_second_trial = model_.last_attempt() && model_.recording() && model_.live() &&
                                  model_.live()->recording_s > 1.5 && model_.live_fused();
    if (stage_ == "record" || stage_ == "record-trial") return !mid_second_trial;
    if (stage_ == "subject-screen") return !(model_.recording() && subject_.shown);
    if (stage_ == "record-verdict") return model_.busy() || !model_.finished();
    if (stage_ == "record-resume") return model_.busy() || (model_.has_session() && !model_.last_preflight());
    if (stage_ == "record-calibration") return model_.busy() || !model_.pending_calibration();
    return false;
  }

  // The session is driven for the mid-trial and verdict pictures; later ones stage it by hand.
  void after_frame(bool /*shown*/) override {
    if (driving_ && stage_ != "record-resume") drive();
  }

 private:
  // One step towards the next trial: create the session, pass its pre-flight, record a block's
  // calibration (then left for the picture), start the next trial.
  void drive() {
    if (!model_.has_session()) {
      const auto dir = scratch_.fresh("record");
      RecordSetupForm& form = tab_.form();
      form.select_protocol("quick");
      RecordSettings settings = form.settings();
      settings.fast = false;
      settings.countdown_s = 0;
      NewSessionSpec spec = form.spec();
      // Trials of 6 s instead of the quick protocol's 3: the pictures taken mid-trial (the tab,
      // the subject screen) all fall inside one trial even at software rendering's frame rate.
      spec.duration_override_s = 6.0;
      tab_.show_setup_error(model_.create(dir, spec, settings));
      return;
    }
    if (model_.busy()) return;
    if (model_.needs_preflight()) {
      if (!model_.last_preflight())
        model_.start_preflight();
      else
        model_.override_preflight("screenshot");
      return;
    }
    if (model_.pending_calibration()) return;
    if (model_.needs_calibration()) {
      model_.start_calibration();
      return;
    }
    if (!model_.finished()) model_.start_trial();
  }

  // The session opened again with its last trial to record once more: the resume notice, the
  // layout to set up and the pre-flight's checklist.
  void reopen_to_redo_last_trial() {
    const std::filesystem::path dir = model_.dir();
    const RecordSettings settings = model_.settings();
    model_.redo(1);
    model_.close();
    const std::string error = model_.open(dir, settings);
    tab_.show_setup_error(error);
    if (error.empty()) model_.start_preflight();
  }

  // A protocol that calibrates each block, on a simulated rig whose controllers stand up to 25 mm
  // and 3 degrees away from the layout: the residual table after the still-hand trial.
  void calibrated_protocol() {
    model_.close();
    const auto dir = scratch_.fresh("record-calibration");
    RecordSetupForm& form = tab_.form();
    form.select_protocol("study-calibrated");
    RecordSettings settings = form.settings();
    settings.fast = true;
    settings.countdown_s = 0;
    settings.sim.calibration_random_translation_mm = 25;
    settings.sim.calibration_random_rotation_deg = 3;
    tab_.show_setup_error(model_.create(dir, form.spec(), settings));
  }

  // A filled-in form, as an operator would leave it before pressing Create.
  void filled_in_form() {
    model_.close();
    driving_ = false;
    RecordSetupForm& form = tab_.form();
    std::snprintf(form.subject, sizeof form.subject, "%s", "S07");
    form.hand_length_mm = 186;
    form.hand_breadth_mm = 84;
    std::snprintf(form.operator_name, sizeof form.operator_name, "%s", "A. Operator");
    std::snprintf(form.notes, sizeof form.notes, "%s", "right-handed, no hand injuries");
    std::snprintf(form.vicon, sizeof form.vicon, "%s", "192.168.10.2:30");
    form.select_protocol("study");
    tab_.refresh_sessions();
  }

  RecordTab& tab_;
  RecordState& model_;
  SubjectScreenLink& subject_;
  CaptureScratch scratch_;  // removed after the shell: the session writing into it has closed
  bool driving_ = false;
  std::string stage_;
};

}  // namespace

std::unique_ptr<TabCapture> make_record_capture(RecordTab& tab, WorkbenchContext& context) {
  return std::make_unique<RecordCapture>(tab, context);
}

}  // namespace lmc::ui
