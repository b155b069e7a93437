#include "ui/model/review/trial_view_job.h"

namespace lmc::ui {

TrialView load_trial_view(const lmc::TrialSources& job, const BatchOptions& options, std::stop_token stop) {
  TrialView view;
  view.trial = job.trial;
  if (stop.stop_requested()) return view;
  ProcessedTrial out;
  auto result = std::make_shared<const TrialAnalysis>(process_sources_in_full(job, options, &out));
  if (stop.stop_requested()) return view;
  view.series = trial_series(*result);
  view.layout = resolve_layout(job, options.layout, nullptr);
  view.warnings = out.warnings;
  view.result = std::move(result);
  return view;
}

void TrialViewJob::start(const lmc::TrialSources& job, const BatchOptions& options) {
  graveyard_.reap();
  job_.abandon_into(graveyard_);
  trial_ = job.trial;
  job_.start([job, options](std::stop_token stop, JobChannel<Report>&) { return load_trial_view(job, options, stop); });
}

}  // namespace lmc::ui
