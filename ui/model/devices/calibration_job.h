#pragma once
// The Devices tab's Calibrate step on a worker (style.md §5.5): reads the calibration trial the
// tab just recorded, calibrates the controllers against each other (core/calibration/) and
// builds the calibrated layout; the UI thread polls state() and, when it is Completed, shows
// outcome()'s residual table and ghost controllers and offers apply_calibration (layout_actions.h).
#include <filesystem>
#include <memory>
#include <string>

#include "core/calibration/calibrate.h"
#include "core/layout/layout.h"
#include "ui/model/jobs/background_job.h"

namespace lmc::ui {

struct CalibrationOutcome {
  calibration::CalibrationResult result;
  Layout calibrated;  // the layout to apply; equal to the input's where nothing was fitted
  std::string table;  // calibration::residual_table(result)
};

class CalibrationJob {
 public:
  // `recording` is an LMC file; `layout` the layout it was recorded with. Everything is copied
  // into the worker.
  void start(std::filesystem::path recording, Layout layout, std::string trial_name);
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
