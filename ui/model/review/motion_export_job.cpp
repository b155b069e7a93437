#include "ui/model/review/motion_export_job.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <numeric>
#include <set>
#include <thread>

#include "core/common/error.h"

namespace fs = std::filesystem;

namespace lmc::ui {
namespace {

// A folder's name for its subfolder, made unique among the names already used (two opened folders
// may both be called S01).
std::string unique_label(const fs::path& folder, std::set<std::string>& used) {
  std::string base = folder.filename().string();
  if (base.empty()) base = folder.parent_path().filename().string();
  if (base.empty()) base = "trials";
  std::string label = base;
  for (int n = 2; !used.insert(label).second; ++n) label = base + "-" + std::to_string(n);
  return label;
}

std::string trials_word(int n) {
  return std::to_string(n) + (n == 1 ? " trial" : " trials");
}

MotionExportOutcome run_trial_exports(const MotionExportPlan& plan, std::stop_token stop,
                                      const std::function<void(int, int)>& progress,
                                      const std::function<void(const std::string&)>& line) {
  MotionExportOutcome out;
  out.folder = plan.folder;
  out.notes = plan.notes;
  // Every run refuses its own existing outputs, but only after the runs before it have written:
  // look at all of them first so a refusal writes nothing at all.
  std::string existing;
  for (const auto& run : plan.trial_runs) {
    if (run.request.force) continue;
    for (const auto& name : run.trials) {
      const fs::path target = run.request.out_dir / (name + export_format_extension(run.request.format));
      if (fs::exists(target)) existing += "\n  " + target.string();
    }
  }
  if (!existing.empty()) {
    throw Error("these files exist (tick \"Replace files that exist\" to replace them); nothing was written:" +
                existing);
  }
  // Runs learn their real number of trials as they start; until then the plan's count stands in.
  std::vector<int> totals;
  for (const auto& run : plan.trial_runs) totals.push_back(static_cast<int>(run.trials.size()));
  const auto sum = [&totals] { return std::accumulate(totals.begin(), totals.end(), 0); };
  int done_before = 0;
  int run_done = 0;  // the running run's trials done
  std::string first_error;
  for (size_t r = 0; r < plan.trial_runs.size(); ++r) {
    if (stop.stop_requested()) {
      out.cancelled = true;
      out.notes.push_back("cancelled after " + trials_word(done_before) + " of " + std::to_string(sum()));
      break;
    }
    TrialExportRequest request = plan.trial_runs[r].request;
    request.on_trial = line;
    run_done = 0;
    request.on_progress = [&, r](int done, int total) {
      totals[r] = total;
      run_done = done;
      if (progress) progress(done_before + done, sum());
    };
    request.should_stop = [&stop] { return stop.stop_requested(); };
    try {
      const TrialExportReport report = export_trials(request);
      out.written.insert(out.written.end(), report.written.begin(), report.written.end());
      out.trials += static_cast<int>(report.exported.size());
      out.left_out += report.left_out;
      // A run counts only its own trials when cancelled; the note below counts the whole export.
      for (const auto& n : report.notes) {
        if (!(report.cancelled && n.rfind("cancelled after ", 0) == 0)) out.notes.push_back(n);
      }
      if (report.cancelled) {
        out.cancelled = true;
        out.notes.push_back("cancelled after " + trials_word(done_before + run_done) + " of " + std::to_string(sum()));
        break;
      }
      done_before += totals[r];
    } catch (const std::exception& e) {
      // One folder that gives nothing must not lose the others' files.
      if (first_error.empty()) first_error = e.what();
      out.notes.push_back(std::string("left out ") + request.out_dir.string() + ": " + e.what());
      out.left_out += static_cast<int>(plan.trial_runs[r].trials.size());
      done_before += totals[r];
    }
  }
  if (out.written.empty() && !first_error.empty()) throw Error(first_error);
  return out;
}

MotionExportOutcome run_bids_export(const MotionExportPlan& plan, std::stop_token stop,
                                    const std::function<void(int, int)>& progress,
                                    const std::function<void(const std::string&)>& line) {
  BidsExportRequest request = *plan.bids;
  request.on_trial = line;
  request.on_progress = progress;
  request.should_stop = [&stop] { return stop.stop_requested(); };
  const BidsExportReport report = export_bids(request);
  MotionExportOutcome out;
  out.folder = report.dataset.empty() ? plan.folder : report.dataset;
  out.bids = true;
  out.trials = report.trials;
  out.subjects = report.subjects;
  out.left_out = report.left_out;
  out.notes = plan.notes;
  out.notes.insert(out.notes.end(), report.notes.begin(), report.notes.end());
  out.cancelled = report.cancelled;
  return out;
}

}  // namespace

int MotionExportPlan::trials_planned() const {
  int n = 0;
  for (const auto& run : trial_runs) n += static_cast<int>(run.trials.size());
  return n;
}

MotionExportPlan trial_export_plan(const std::vector<ReviewTrial>& trials, const std::vector<int>& chosen,
                                   const BatchOptions& options, const FolderLengthCorrections& corrections,
                                   const fs::path& out_dir, ExportFormat format, ExportAxes axes, bool force) {
  MotionExportPlan plan;
  plan.folder = out_dir;
  // The chosen trials by opened folder, folders in the order their first trial was chosen.
  std::vector<fs::path> folders;
  std::map<fs::path, std::vector<int>> by_folder;
  for (const int k : chosen) {
    if (k < 0 || k >= static_cast<int>(trials.size())) continue;
    const fs::path& folder = trials[static_cast<size_t>(k)].folder;
    if (by_folder.find(folder) == by_folder.end()) folders.push_back(folder);
    by_folder[folder].push_back(k);
  }
  std::set<std::string> labels;
  for (const auto& folder : folders) {
    const std::vector<int>& picked = by_folder[folder];
    const auto in_folder =
        std::count_if(trials.begin(), trials.end(), [&](const ReviewTrial& t) { return t.folder == folder; });
    std::set<int> unique(picked.begin(), picked.end());
    TrialExportRun run;
    TrialExportRequest& r = run.request;
    if (static_cast<long>(unique.size()) == in_folder) {
      r.inputs.push_back(folder);
    } else {
      for (const int k : unique) r.inputs.push_back(trials[static_cast<size_t>(k)].job.lmc);
    }
    for (const int k : unique) run.trials.push_back(trials[static_cast<size_t>(k)].job.trial);
    r.out_dir = folders.size() == 1 ? out_dir : out_dir / unique_label(folder, labels);
    r.format = format;
    r.axes = axes;
    r.force = force;
    r.session = folder_options(options, corrections, folder);
    plan.trial_runs.push_back(std::move(run));
  }
  return plan;
}

MotionExportPlan bids_export_plan(const std::vector<fs::path>& folders, const BatchOptions& options,
                                  const FolderLengthCorrections& corrections, const fs::path& out_dir,
                                  const std::optional<fs::path>& anonymise_key, bool force) {
  MotionExportPlan plan;
  plan.folder = out_dir;
  BidsExportRequest r;
  r.inputs = folders;
  r.out_dir = out_dir;
  r.anonymise = anonymise_key.has_value();
  if (anonymise_key) r.anonymise_key = *anonymise_key;
  r.force = force;
  r.session = options;
  plan.bids = std::move(r);
  if (options.process.method == FusionMethod::kDefault) {
    for (const auto& folder : folders) {
      if (corrections.count(folder) > 0) {
        plan.notes.push_back(
            folder.filename().string() +
            ": its finger-length correction is not applied in the dataset (a dataset is processed with one "
            "set of options for every subject)");
      }
    }
  }
  return plan;
}

MotionExportOutcome run_motion_export(const MotionExportPlan& plan, std::stop_token stop,
                                      const std::function<void(int, int)>& progress,
                                      const std::function<void(const std::string&)>& line) {
  if (plan.bids) return run_bids_export(plan, stop, progress, line);
  if (plan.trial_runs.empty()) throw Error("no trial to export: the table shows none, or none is selected");
  return run_trial_exports(plan, stop, progress, line);
}

void MotionExportJob::start(MotionExportPlan plan) {
  folder_ = plan.folder;
  plan_notes_ = plan.notes;
  bids_ = plan.bids.has_value();
  ++runs_;
  job_.start([plan = std::move(plan)](std::stop_token stop, JobChannel<Report>& channel) {
    return run_motion_export(
        plan, stop, [&channel](int done, int total) { channel.set_progress(done, total); },
        [&channel](const std::string& line) { channel.set_stage(line); });
  });
}

void MotionExportJob::wait() const {
  while (running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

}  // namespace lmc::ui
