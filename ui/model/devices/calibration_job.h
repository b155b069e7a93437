#pragma once
// The Devices tab's Calibrate step on a worker (docs/architecture.md): calibrates the controllers from a
// trial file, against a Vicon file or against each other, with the one sequence `lmc calibrate`
// runs (core/calibration/calibrate_trial.h); the UI thread polls state() and, when it is
// Completed, shows outcome()'s residuals and ghost controllers and offers apply_calibration
// (layout_actions.h). The work takes a fraction of a second, so cancel() only stops the result
// from counting (the state ends Cancelled).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/calibration/calibrate_trial.h"
#include "core/layout/layout.h"
#include "ui/model/jobs/background_job.h"

namespace lmc::ui {

struct CalibrationOutcome {
  std::string trial;  // the trial's name
  CalibrationResult result;
  Layout calibrated;  // the layout to apply; equal to the input's where nothing was fitted
  std::string table;  // residual_table(result)
  std::vector<std::string> file_warnings, notes;
};

class CalibrationJob {
 public:
  // `layout` is the layout the trial was recorded with; everything is copied into the worker.
  // An empty request.when_utc is filled with the time the job starts.
  void start(TrialCalibrationRequest request, Layout layout);
  void cancel() { job_.cancel(); }
  void cancel_and_join() { job_.cancel_and_join(); }

  JobState state() const { return job_.state(); }
  bool running() const { return job_.running(); }
  std::string stage() const { return job_.stage(); }
  std::shared_ptr<const CalibrationOutcome> outcome() const { return job_.result(); }
  std::string error() const { return job_.error(); }

 private:
  struct NoReport {};
  BackgroundJob<CalibrationOutcome, NoReport> job_;
};

}  // namespace lmc::ui
