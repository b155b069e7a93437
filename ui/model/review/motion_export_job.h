#pragma once
// Exports for motion-analysis tools from the Review tab, in the background: chosen trials as C3D or
// TRC (core's export_trials) or the opened sessions as a BIDS-motion dataset (core's export_bids).
// Trials are processed with the options the tab shows them with (its fusion method and each
// folder's finger-length correction), so the exported points are the ones on screen. The job owns
// a copy of its plan; the worker never sees the tab's state.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/export/bids_dataset.h"
#include "core/export/trial_points.h"
#include "ui/model/jobs/background_job.h"
#include "ui/model/review/review_batch_job.h"

namespace lmc::ui {

// One export_trials run: the chosen trials of one opened folder, with that folder's options.
struct TrialExportRun {
  TrialExportRequest request;       // its callbacks are set by the run
  std::vector<std::string> trials;  // the names planned: existing outputs are refused before any run
};

struct MotionExportPlan {
  std::filesystem::path folder;            // what a finished export names and opens
  std::vector<TrialExportRun> trial_runs;  // C3D / TRC
  std::optional<BidsExportRequest> bids;   // BIDS
  std::vector<std::string> notes;          // known before it runs (what the export cannot carry over)
  int trials_planned() const;
};

// `chosen` (indices into `trials`) as C3D or TRC into `out_dir`. Each opened folder's trials are one
// run with that folder's options; trials of several folders go into a subfolder per folder (named
// after it), because subjects' trials share names (S01's and S02's Naiv_Index101). A run's input is
// the folder itself when every trial of it is chosen (the trials the batch found, exactly), else the
// chosen recordings.
MotionExportPlan trial_export_plan(const std::vector<ReviewTrial>& trials, const std::vector<int>& chosen,
                                   const BatchOptions& options, const FolderLengthCorrections& corrections,
                                   const std::filesystem::path& out_dir, ExportFormat format, ExportAxes axes,
                                   bool force);

// The opened folders as one BIDS dataset at `out_dir`; with `anonymise_key`, subjects become sub-01,
// sub-02, … and the key is written there. A dataset is processed with one set of options: finger-
// length corrections chosen per folder are not applied, and the plan's notes say so.
MotionExportPlan bids_export_plan(const std::vector<std::filesystem::path>& folders, const BatchOptions& options,
                                  const FolderLengthCorrections& corrections, const std::filesystem::path& out_dir,
                                  const std::optional<std::filesystem::path>& anonymise_key, bool force);

struct MotionExportOutcome {
  std::filesystem::path folder;
  bool bids = false;
  std::vector<std::filesystem::path> written;  // C3D / TRC files
  int trials = 0;                              // trials exported
  int subjects = 0;                            // BIDS
  int left_out = 0;
  std::vector<std::string> notes;
  bool cancelled = false;
};

// The work itself, for the job and for tests (runs on the calling thread). `progress` gets trials
// done and planned, `line` each trial written or left out. Throws lmc::Error when nothing could be
// exported, or when outputs exist and the plan does not replace them (nothing is written then).
MotionExportOutcome run_motion_export(const MotionExportPlan& plan, std::stop_token stop,
                                      const std::function<void(int done, int total)>& progress,
                                      const std::function<void(const std::string& line)>& line);

class MotionExportJob {
 public:
  void start(MotionExportPlan plan);
  void cancel() { job_.cancel(); }
  void wait() const;  // until it has finished (tests, captures)

  JobState state() const { return job_.state(); }
  bool running() const { return job_.running(); }
  long long done() const { return job_.done(); }
  long long total() const { return job_.total(); }
  double fraction() const { return job_.fraction(); }
  double elapsed_seconds() const { return job_.elapsed_seconds(); }
  std::optional<double> eta_seconds() const { return job_.eta_seconds(); }
  // The last trial written or left out ("wrote …/Naiv_Index101.c3d (…)").
  std::string current_line() const { return job_.stage(); }
  // Finished or cancelled: what was written; null while running, before a run and after a failure.
  std::shared_ptr<const MotionExportOutcome> outcome() const { return job_.result(); }
  std::string error() const { return job_.error(); }
  // The plan's folder and notes, from the moment it starts.
  const std::filesystem::path& folder() const { return folder_; }
  const std::vector<std::string>& plan_notes() const { return plan_notes_; }
  bool is_bids() const { return bids_; }
  // Exports started so far: tells a new outcome from one already reported (a failure can begin and
  // end between two frames).
  int runs() const { return runs_; }

 private:
  struct Report {};
  BackgroundJob<MotionExportOutcome, Report> job_;
  std::filesystem::path folder_;
  std::vector<std::string> plan_notes_;
  bool bids_ = false;
  int runs_ = 0;
};

}  // namespace lmc::ui
