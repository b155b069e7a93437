#pragma once
// The Review tab's state: the folders a researcher opened, their processed trials (the
// batch job's result), the table's filter, the selected trial and its full view, and the x range
// the stacked plots share. Panels read it and call its actions; processing happens in the jobs.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/review/agreement_table.h"
#include "core/review/visibility_map.h"
#include "ui/model/plot/linked_x_range.h"
#include "ui/model/review/motion_export_job.h"
#include "ui/model/review/review_batch_job.h"
#include "ui/model/review/trial_view_job.h"
#include "ui/model/text/markdown_blocks.h"

namespace lmc::ui {

// Empty fields match everything.
struct TrialFilter {
  std::string subject, layout, pose, motion, status;
  std::string text;  // part of the trial name, any case
  bool operator==(const TrialFilter&) const = default;
};

bool matches(const TrialRow& row, const TrialFilter& filter);

// The table's columns; kVisibility is followed by one column per controller (kVisibility + d).
enum class TrialColumn { kSubject, kTrial, kLayout, kPose, kMotion, kStatus, kLengthDiff, kRomDiff, kLag, kVisibility };

// The distinct values of one text column, sorted, for the filter's combo boxes.
std::vector<std::string> distinct_values(const std::vector<ReviewTrial>& trials, TrialColumn column);

struct TrialSort {
  int column = static_cast<int>(TrialColumn::kSubject);  // a TrialColumn, or kVisibility + controller index
  bool ascending = true;
  bool operator==(const TrialSort&) const = default;
};

// Sorts indices into `trials` by the column; unknown numbers (NaN) go last either way, ties keep
// folder and trial order.
void sort_trials(const std::vector<ReviewTrial>& trials, const TrialSort& sort, std::vector<int>& indices);

// Which trials Export… writes: the one selected, or every one the table shows (its filter).
enum class TrialsToExport { kSelected, kShown };

class ReviewState {
 public:
  ReviewState();

  // ---- actions -------------------------------------------------------------------------------
  // Adds a folder (a subject session, a folder of trials, or a trial's folder) and processes what
  // is open again (cached trials come back at once). A folder already open is not added twice.
  void open_folder(const std::filesystem::path& folder) { open_folders({folder}); }
  // One processing run for all. A folder that does not exist is not opened: problem() names it
  // ("…: no such folder"), so no chip stands for a folder that is not there.
  void open_folders(const std::vector<std::filesystem::path>& folders);
  void close_folder(const std::filesystem::path& folder);
  void set_method(FusionMethod method);  // processes everything again with the other fusion
  // A subject's finger-length correction (`lmc length-correction fit`) for the trials of one opened
  // folder, applied after the default fusion, never to the reference fusion (the study's algorithm).
  // Reads the file at once: one that cannot be used changes nothing and says why (problem()), naming
  // the file. Processes again (the cache keeps corrected and plain results apart).
  bool set_length_correction(const std::filesystem::path& folder, const std::filesystem::path& file);
  void clear_length_correction(const std::filesystem::path& folder);
  void reprocess();
  void cancel() { batch_job_.cancel(); }
  void set_filter(const TrialFilter& filter) { filter_ = filter; }
  void set_sort(const TrialSort& sort) { sort_ = sort; }
  // Selects a trial (an index into trials()) and loads its full view in the background.
  void select(int index);
  // The trial shown first after processing when none is selected, or at once when the trials are
  // in (by name; `--capture` uses LMC_REVIEW_TRIAL to picture an interesting one). Default: the
  // first trial with Vicon.
  void prefer_trial(std::string name);
  // The cache folder (tests point it at a scratch folder; default: the user's cache).
  void set_cache_dir(std::filesystem::path dir) { cache_dir_ = std::move(dir); }

  // Every frame: picks up finished jobs.
  void update();

  // ---- what panels read ----------------------------------------------------------------------
  const std::vector<std::filesystem::path>& folders() const { return folders_; }
  const ReviewBatchJob& batch_job() const { return batch_job_; }
  const std::vector<ReviewTrial>& trials() const;
  const ReviewBatch* batch() const { return batch_.get(); }
  const TrialFilter& filter() const { return filter_; }
  std::vector<int> visible_trials() const;  // indices passing the filter, in the sort's order
  const TrialSort& sort() const { return sort_; }
  int selected() const { return selected_; }
  const TrialViewJob& view_job() const { return view_job_; }
  std::shared_ptr<const TrialView> view() const { return view_; }
  const std::shared_ptr<LinkedXRange>& x_range() const { return x_range_; }
  FusionMethod method() const { return options_.process.method; }
  // The folder's correction, or nullptr; whether it is applied also depends on method().
  const FolderLengthCorrection* length_correction(const std::filesystem::path& folder) const;
  bool busy() const {
    return batch_job_.running() || view_job_.running() || export_job_.running() || motion_export_.running();
  }
  // Agreement and the visibility map over the trials the table shows (its filter), recomputed only
  // when the batch, the filter or the motion changes: 80 trials take about a millisecond.
  struct Agreement {
    AgreementTable table;
    VisibilityMap visibility;
    std::vector<AgreementTrial> inputs;       // what they were computed from (for exports)
    std::vector<MarkdownBlock> study_tables;  // the study's headline tables (lmc report's), as blocks
  };
  const Agreement& agreement() const;
  void set_agreement_motion(const std::string& motion) { agreement_motion_ = motion; }
  const std::string& agreement_motion() const { return agreement_motion_; }
  // ---- exports (core/review/review_export.h), on a worker thread ---------------------------------
  // Everything the Agreement view shows, over the trials the table shows, into `dir`.
  void export_agreement(const std::filesystem::path& dir);
  // The selected trial's figure and series into `dir` (nothing when no trial is loaded).
  void export_trial(const std::filesystem::path& dir, bool each_controller);
  bool exporting() const { return export_job_.running(); }
  // The last export's outcome in words ("wrote 62 files to …" or the error); empty before one.
  const std::string& export_message() const { return export_message_; }
  // ---- exports for motion-analysis tools (core/export: C3D, TRC, BIDS), on a worker thread -------
  // The chosen trials as C3D or TRC into `dir`, processed as the tab shows them (its fusion and each
  // folder's length correction). Starting again while one runs cancels that one.
  void export_trial_points(TrialsToExport which, const std::filesystem::path& dir, ExportFormat format, ExportAxes axes,
                           bool replace);
  // The opened folders as a BIDS-motion dataset at `dir`; with `anonymise_key`, subject ids are
  // replaced and the key is written there.
  void export_bids_dataset(const std::filesystem::path& dir, const std::optional<std::filesystem::path>& anonymise_key,
                           bool replace);
  void cancel_motion_export() { motion_export_.cancel(); }
  const MotionExportJob& motion_export() const { return motion_export_; }
  // The last problem to show (a failed job); empty when none.
  const std::string& problem() const { return problem_; }

 private:
  int preferred_index() const;  // index of the preferred trial in trials(), or -1
  std::vector<std::filesystem::path> folders_;
  BatchOptions options_;
  FolderLengthCorrections corrections_;
  std::filesystem::path cache_dir_;
  ReviewBatchJob batch_job_;
  std::shared_ptr<const ReviewBatch> batch_;
  TrialFilter filter_;
  TrialSort sort_;
  int selected_ = -1;
  std::string selected_trial_;  // folder and name, kept across a reprocess
  std::string preferred_trial_;
  TrialViewJob view_job_;
  std::shared_ptr<const TrialView> view_;
  std::shared_ptr<LinkedXRange> x_range_ = std::make_shared<LinkedXRange>();
  std::string problem_;
  std::string agreement_motion_;
  struct AgreementKey {
    const ReviewBatch* batch = nullptr;
    TrialFilter filter;
    std::string motion;
    bool operator==(const AgreementKey&) const = default;
  };
  mutable std::optional<AgreementKey> agreement_key_;
  mutable Agreement agreement_;
  struct ExportReport {};
  BackgroundJob<std::vector<std::filesystem::path>, ExportReport> export_job_;
  std::filesystem::path export_dir_;
  std::string export_message_;
  MotionExportJob motion_export_;
};

}  // namespace lmc::ui
