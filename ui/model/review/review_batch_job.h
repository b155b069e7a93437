#pragma once
// Processing what the Review tab opened, in the background: every opened folder's
// trials (a subject session's accepted attempts, or every trial in a plain folder) through core's
// process_session_cached on a worker thread, with progress, ETA and cancel. Cached trials come back
// at once; a cancelled batch keeps what was done (the rest are rows marked "cancelled").
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/processing/batch.h"
#include "core/review/folder_length_corrections.h"
#include "core/review/trial_row.h"
#include "ui/model/jobs/background_job.h"

namespace lmc::ui {

struct ReviewTrial {
  std::filesystem::path folder;  // the opened folder it came from
  lmc::TrialSources job;         // core's (processing), not the Devices tab's ui::TrialSources
  ProcessedTrial outcome;
  bool from_cache = false;
  TrialRow row;
};

struct ReviewBatch {
  std::vector<ReviewTrial> trials;  // folder order, then trial order
  std::vector<std::string> notes;   // files skipped and why, folders that could not be read
  std::vector<std::string> cache_warnings;
  int processed_now = 0, from_cache = 0;
};

struct ReviewBatchInput {
  std::vector<std::filesystem::path> folders;
  BatchOptions options;             // stop/on_progress are set by the job
  std::filesystem::path cache_dir;  // empty: no cache
  // A finger-length correction per folder (a subject's), applied as core/review/folder_length_corrections.h says.
  FolderLengthCorrections corrections;
};

// The work itself, for the job and for tests (runs on the calling thread).
ReviewBatch run_review_batch(const ReviewBatchInput& input, std::stop_token stop,
                             const std::function<void(int done, int total)>& progress);

struct ReviewBatchReport {};

class ReviewBatchJob {
 public:
  void start(ReviewBatchInput input);
  void cancel() { job_.cancel(); }
  JobState state() const { return job_.state(); }
  bool running() const { return job_.running(); }
  double fraction() const { return job_.fraction(); }
  long long done() const { return job_.done(); }
  long long total() const { return job_.total(); }
  std::optional<double> eta_seconds() const { return job_.eta_seconds(); }
  std::string error() const { return job_.error(); }
  std::shared_ptr<const ReviewBatch> result() const { return job_.result(); }

 private:
  BackgroundJob<ReviewBatch, ReviewBatchReport> job_;
};

}  // namespace lmc::ui
