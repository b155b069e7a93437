#pragma once
// The selected trial in full: the cache keeps only summaries, so clicking a trial
// processes it again on a worker thread (well under a second for a study trial) and keeps its
// series for the stacked plots, and the whole result for the 3D replay. Selecting another trial
// abandons the previous run instead of waiting for it.
#include <memory>
#include <string>

#include "core/processing/batch.h"
#include "core/review/trial_series.h"
#include "ui/model/jobs/background_job.h"

namespace lmc::ui {

struct TrialView {
  std::string trial;
  TrialSeries series;
  std::shared_ptr<const TrialAnalysis> result;
  Layout layout;  // the one the trial was processed with (the 3D replay draws its controllers)
  std::vector<std::string> warnings;
};

// The work, for the job and for tests: throws lmc::Error with the trial's message when it fails.
// A stop request before or after processing returns an empty view (the job is then cancelled).
TrialView load_trial_view(const lmc::TrialSources& job, const BatchOptions& options, std::stop_token stop = {});

class TrialViewJob {
 public:
  void start(const lmc::TrialSources& job, const BatchOptions& options);
  bool running() const { return job_.running(); }
  JobState state() const { return job_.state(); }
  std::string error() const { return job_.error(); }
  std::shared_ptr<const TrialView> result() const { return job_.result(); }
  const std::string& trial() const { return trial_; }

 private:
  struct Report {};
  JobGraveyard graveyard_;
  BackgroundJob<TrialView, Report> job_;
  std::string trial_;
};

}  // namespace lmc::ui
