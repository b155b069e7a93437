#include "ui/model/review/trial_view_job.h"


#include "core/common/error.h"
#include "core/io/vicon_mapping.h"

namespace lmc::ui {

TrialView load_trial_view(const lmc::TrialJob& job, const SessionOptions& options) {
  TrialView view;
  view.trial = job.trial;
  SessionOptions o = options;
  std::shared_ptr<TrialResult> kept;
  o.on_result = [&kept](const TrialResult& r) { kept = std::make_shared<TrialResult>(r); };
  o.compare_methods = false;
  const ViconMapping mapping = o.mapping ? load_vicon_mapping(*o.mapping) : default_vicon_mapping();
  TrialOutcome out = process_job(job, o, mapping);
  if (!out.ok || !kept) throw Error(job.trial + ": " + (out.error.empty() ? "processing gave no result" : out.error));
  view.series = trial_series(*kept);
  view.layout = resolve_layout(job, o.layout, nullptr);
  view.warnings = out.warnings;
  view.result = std::move(kept);
  return view;
}

void TrialViewJob::start(const lmc::TrialJob& job, const SessionOptions& options) {
  graveyard_.reap();
  job_.abandon_into(graveyard_);
  trial_ = job.trial;
  job_.start([job, options](std::stop_token, JobChannel<Report>&) { return load_trial_view(job, options); });
}

}  // namespace lmc::ui
