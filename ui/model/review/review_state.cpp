#include "ui/model/review/review_state.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "core/processing/length_correction_json.h"
#include "core/processing/process_options_json.h"
#include "core/reports/session_report.h"
#include "core/results/processing_cache.h"
#include "core/review/review_export.h"

namespace lmc::ui {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

const std::string& column_value(const TrialRow& row, TrialColumn column, std::string& scratch) {
  switch (column) {
    case TrialColumn::kSubject:
      return row.subject;
    case TrialColumn::kLayout:
      return row.layout;
    case TrialColumn::kPose:
      return row.pose;
    case TrialColumn::kMotion:
      return row.motion;
    case TrialColumn::kStatus:
      scratch = trial_row_status_name(row.status);
      return scratch;
    default:
      return row.trial;
  }
}

const std::vector<ReviewTrial> kNoTrials;

double numeric_value(const TrialRow& row, int column) {
  const int vis = static_cast<int>(TrialColumn::kVisibility);
  if (column >= vis) {
    const size_t d = static_cast<size_t>(column - vis);
    return d < row.visibility_rate.size() ? row.visibility_rate[d] : std::nan("");
  }
  switch (static_cast<TrialColumn>(column)) {
    case TrialColumn::kLengthDiff:
      return row.finger_length_diff_mm;
    case TrialColumn::kRomDiff:
      return row.rom_abs_diff_deg;
    case TrialColumn::kLag:
      return row.lag_ms;
    default:
      return std::nan("");
  }
}

bool is_numeric_column(int column) {
  return column >= static_cast<int>(TrialColumn::kLengthDiff);
}

// Trials of different subjects share names (S01's and S02's Naiv_Index101): folder and name.
std::string trial_key(const ReviewTrial& t) {
  return t.folder.string() + '\n' + t.job.trial;
}

}  // namespace

bool matches(const TrialRow& row, const TrialFilter& f) {
  const auto field_ok = [](const std::string& want, const std::string& have) { return want.empty() || want == have; };
  if (!field_ok(f.subject, row.subject) || !field_ok(f.layout, row.layout) || !field_ok(f.pose, row.pose) ||
      !field_ok(f.motion, row.motion) || !field_ok(f.status, trial_row_status_name(row.status))) {
    return false;
  }
  return f.text.empty() || lower(row.trial).find(lower(f.text)) != std::string::npos;
}

std::vector<std::string> distinct_values(const std::vector<ReviewTrial>& trials, TrialColumn column) {
  std::set<std::string> values;
  std::string scratch;
  for (const auto& t : trials) values.insert(column_value(t.row, column, scratch));
  return {values.begin(), values.end()};
}

ReviewState::ReviewState() {
  cache_dir_ = ProcessingCache::in_user_cache().dir();
}

const std::vector<ReviewTrial>& ReviewState::trials() const {
  return batch_ ? batch_->trials : kNoTrials;
}

void ReviewState::open_folders(const std::vector<std::filesystem::path>& folders) {
  std::string missing;
  bool added = false;
  for (const auto& folder : folders) {
    std::error_code ec;
    if (!std::filesystem::exists(folder, ec)) {
      missing += (missing.empty() ? "" : "; ") + folder.string() + ": no such folder";
      continue;
    }
    const auto normal = folder.lexically_normal();
    if (std::find(folders_.begin(), folders_.end(), normal) == folders_.end()) {
      folders_.push_back(normal);
      added = true;
    }
  }
  if (added) reprocess();
  if (!missing.empty()) problem_ = "not opened: " + missing;
}

void ReviewState::close_folder(const std::filesystem::path& folder) {
  folders_.erase(std::remove(folders_.begin(), folders_.end(), folder), folders_.end());
  corrections_.erase(folder);
  reprocess();
}

bool ReviewState::set_length_correction(const std::filesystem::path& folder, const std::filesystem::path& file) {
  try {
    corrections_[folder] = FolderLengthCorrection{file, read_length_correction(file)};
  } catch (const std::exception& e) {
    problem_ = std::string("length correction not used: ") + e.what();
    return false;
  }
  reprocess();
  return true;
}

void ReviewState::clear_length_correction(const std::filesystem::path& folder) {
  if (corrections_.erase(folder) > 0) reprocess();
}

const FolderLengthCorrection* ReviewState::length_correction(const std::filesystem::path& folder) const {
  const auto it = corrections_.find(folder);
  return it != corrections_.end() ? &it->second : nullptr;
}

void ReviewState::set_method(FusionMethod method) {
  if (options_.process.method == method) return;
  options_.process.method = method;
  reprocess();
}

void ReviewState::reprocess() {
  problem_.clear();
  if (selected_ >= 0 && selected_ < static_cast<int>(trials().size())) selected_trial_ = trial_key(trials()[selected_]);
  batch_job_.start(ReviewBatchInput{folders_, options_, cache_dir_, corrections_});
}

void ReviewState::select(int index) {
  if (index < 0 || index >= static_cast<int>(trials().size())) return;
  selected_ = index;
  const ReviewTrial& t = trials()[index];
  selected_trial_ = trial_key(t);
  view_.reset();
  view_job_.start(t.job, folder_options(options_, corrections_, t.folder));
}

void ReviewState::prefer_trial(std::string name) {
  preferred_trial_ = std::move(name);
  // The trials may be in already (processed while other tabs were shown), with the first one that
  // has Vicon chosen for want of a choice: take the preferred one now.
  if (const int k = preferred_index(); k >= 0) select(k);
}

int ReviewState::preferred_index() const {
  if (preferred_trial_.empty()) return -1;
  for (size_t k = 0; k < trials().size(); ++k) {
    if (trials()[k].job.trial == preferred_trial_) return static_cast<int>(k);
  }
  return -1;
}

void ReviewState::update() {
  if (job_finished(batch_job_.state())) {
    if (auto r = batch_job_.result(); r && r != batch_) {
      batch_ = r;
      // Keep the trial a person was looking at selected after a reprocess, and load it again: the
      // method or its files may have changed.
      selected_ = -1;
      for (size_t k = 0; k < batch_->trials.size(); ++k) {
        if (trial_key(batch_->trials[k]) == selected_trial_) selected_ = static_cast<int>(k);
      }
      // Nothing chosen yet: the preferred trial, else the first that has Vicon, so the view is
      // never empty for no reason.
      if (selected_ < 0) selected_ = preferred_index();
      if (selected_ < 0) {
        for (size_t k = 0; k < batch_->trials.size() && selected_ < 0; ++k) {
          if (batch_->trials[k].row.status == TrialRowStatus::kOk) selected_ = static_cast<int>(k);
        }
      }
      if (selected_ >= 0) select(selected_);
    }
    if (batch_job_.state() == JobState::kFailed && problem_.empty()) problem_ = batch_job_.error();
  }
  if (job_finished(export_job_.state()) && export_message_ == "exporting...") {
    if (auto files = export_job_.result(); files && export_job_.state() == JobState::kCompleted) {
      export_message_ = "wrote " + std::to_string(files->size()) + " files to " + export_dir_.string();
    } else {
      export_message_ = "export failed: " + export_job_.error();
    }
  }
  if (job_finished(view_job_.state())) {
    if (auto v = view_job_.result(); v && v != view_) {
      view_ = v;
      if (!v->series.time_s.empty()) {
        x_range_->set_extent(v->series.time_s.front(), v->series.time_s.back());
        // The replay starts mid-trial: the first frames often have no hand yet.
        x_range_->cursor = 0.5 * (v->series.time_s.front() + v->series.time_s.back());
      }
    }
    if (view_job_.state() == JobState::kFailed && problem_.empty()) problem_ = view_job_.error();
  }
}

void sort_trials(const std::vector<ReviewTrial>& trials, const TrialSort& sort, std::vector<int>& indices) {
  const auto less = [&](int a, int b) {
    const TrialRow& ra = trials[static_cast<size_t>(a)].row;
    const TrialRow& rb = trials[static_cast<size_t>(b)].row;
    if (is_numeric_column(sort.column)) {
      const double va = numeric_value(ra, sort.column), vb = numeric_value(rb, sort.column);
      const bool fa = std::isfinite(va), fb = std::isfinite(vb);
      if (fa != fb) return fa;  // unknown last, whatever the direction
      if (fa && va != vb) return sort.ascending ? va < vb : va > vb;
      return a < b;
    }
    std::string sa, sb;
    const std::string& ta = column_value(ra, static_cast<TrialColumn>(sort.column), sa);
    const std::string& tb = column_value(rb, static_cast<TrialColumn>(sort.column), sb);
    if (ta != tb) return sort.ascending ? ta < tb : ta > tb;
    return a < b;
  };
  std::stable_sort(indices.begin(), indices.end(), less);
}

void ReviewState::export_agreement(const std::filesystem::path& dir) {
  ReviewExportInput in;
  in.trials = agreement().inputs;
  in.agreement.motion = agreement_motion_;
  for (const auto& f : folders_) in.inputs.push_back(f.string());
  in.method = fusion_method_name(options_.process.method);
  in.parameters = process_options_json(options_.process);
  add_length_correction_files(in.parameters, options_.process.method, corrections_);
  export_dir_ = dir;
  export_message_ = "exporting...";
  export_job_.start(
      [dir, in](std::stop_token stop, JobChannel<ExportReport>&) { return write_review_exports(dir, in, stop); });
}

void ReviewState::export_trial(const std::filesystem::path& dir, bool each_controller) {
  if (!view_ || !view_->result) return;
  auto view = view_;
  const std::string method = fusion_method_name(options_.process.method);
  // The options this trial was processed with: the result says which length correction it got.
  ProcessOptions trial_options = options_.process;
  trial_options.length_correction = view->result->length_correction;
  const nlohmann::json parameters = process_options_json(trial_options);
  export_dir_ = dir;
  export_message_ = "exporting...";
  export_job_.start([dir, view, method, parameters, each_controller](std::stop_token stop, JobChannel<ExportReport>&) {
    return write_trial_export(dir, view->series, {view->result->lmc_source}, method, parameters, each_controller, stop);
  });
}

void ReviewState::export_trial_points(TrialsToExport which, const std::filesystem::path& dir, ExportFormat format,
                                      ExportAxes axes, bool replace) {
  std::vector<int> chosen;
  if (which == TrialsToExport::kShown) {
    chosen = visible_trials();
  } else if (selected_ >= 0) {
    chosen.push_back(selected_);
  }
  motion_export_.start(trial_export_plan(trials(), chosen, options_, corrections_, dir, format, axes, replace));
}

void ReviewState::export_bids_dataset(const std::filesystem::path& dir,
                                      const std::optional<std::filesystem::path>& anonymise_key, bool replace) {
  motion_export_.start(bids_export_plan(folders_, options_, corrections_, dir, anonymise_key, replace));
}

std::vector<int> ReviewState::visible_trials() const {
  std::vector<int> out;
  for (size_t k = 0; k < trials().size(); ++k) {
    if (matches(trials()[k].row, filter_)) out.push_back(static_cast<int>(k));
  }
  sort_trials(trials(), sort_, out);
  return out;
}

const ReviewState::Agreement& ReviewState::agreement() const {
  const AgreementKey key{batch_.get(), filter_, agreement_motion_};
  if (agreement_key_ && *agreement_key_ == key) return agreement_;
  agreement_ = {};
  for (const int k : visible_trials()) {
    const ReviewTrial& t = trials()[static_cast<size_t>(k)];
    if (t.outcome.ok) agreement_.inputs.push_back(agreement_trial(t.row.subject, t.outcome.summary));
  }
  AgreementOptions options;
  options.motion = agreement_motion_;
  agreement_.table = agreement_table(agreement_.inputs, options);
  agreement_.visibility = visibility_map(agreement_.inputs);
  std::vector<ReportInput> report;
  for (const auto& t : agreement_.inputs) report.push_back({t.subject, t.summary});
  if (!report.empty()) agreement_.study_tables = parse_markdown_blocks(build_session_report(report).markdown);
  agreement_key_ = key;
  return agreement_;
}

}  // namespace lmc::ui
