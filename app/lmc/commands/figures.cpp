// lmc figures — the Review tab's tables and figures headless: processes the given
// subject sessions or folders of trials (through the same cache as the workbench, so a session the
// Review tab opened is instant here too), then writes the agreement table, a Bland–Altman plot per
// layout × pose group and measure, the study's visibility map and headline tables, and, for each
// --trial, its angles and finger lengths against Vicon (core/review/review_export.h). A folder's
// finger-length correction (--length-correction FOLDER=FILE) applies as in the Review tab
// (core/review/folder_length_corrections.h).
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/processing/length_correction_json.h"
#include "core/processing/process_options_json.h"
#include "core/results/processing_cache.h"
#include "core/review/folder_length_corrections.h"
#include "core/review/review_export.h"
#include "core/session/session_trials.h"

namespace {

namespace fs = std::filesystem;

struct FiguresArgs {
  std::vector<std::string> inputs;
  std::string out;
  std::string method = "default";
  std::string motion;
  std::vector<std::string> trials;
  std::vector<std::string> length_corrections;  // FOLDER=FILE, FOLDER one of the inputs
  bool each_controller = false;
  bool no_cache = false;
};

std::string subject_of(const fs::path& folder) {
  return folder.filename().empty() ? folder.parent_path().filename().string() : folder.filename().string();
}

// --length-correction FOLDER=FILE: the folder is one of the inputs as given (a path may hold '=',
// so the split is where the left part names an input).
lmc::FolderLengthCorrections read_corrections(const FiguresArgs& a) {
  lmc::FolderLengthCorrections out;
  for (const auto& spec : a.length_corrections) {
    std::optional<fs::path> folder;
    std::string file;
    for (size_t eq = spec.find('='); eq != std::string::npos && !folder; eq = spec.find('=', eq + 1)) {
      for (const auto& input : a.inputs) {
        if (fs::path(spec.substr(0, eq)).lexically_normal() == fs::path(input).lexically_normal()) {
          folder = fs::path(input).lexically_normal();
          file = spec.substr(eq + 1);
        }
      }
    }
    if (!folder || file.empty())
      throw lmc::Error("--length-correction " + spec + ": expected FOLDER=FILE with FOLDER one of the inputs");
    out[*folder] = lmc::FolderLengthCorrection{file, lmc::read_length_correction(file)};
  }
  return out;
}

void run_figures(const FiguresArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  lmc::BatchOptions options;
  options.process.method = lmc::fusion_method_from_name(a.method);
  const lmc::FolderLengthCorrections corrections = read_corrections(a);
  if (!corrections.empty() && options.process.method != lmc::FusionMethod::kDefault) {
    throw lmc::Error(
        "--length-correction applies to the default fusion only: the reference method stays the study's algorithm");
  }
  std::vector<lmc::TrialSources> jobs;
  std::vector<fs::path> folder_of;
  std::vector<std::string> subjects;
  std::vector<std::string> notes;
  for (const auto& input : a.inputs) {
    for (auto& j : lmc::trial_sources_for_input(input, std::nullopt, &notes)) {
      jobs.push_back(std::move(j));
      folder_of.push_back(fs::path(input).lexically_normal());
      subjects.push_back(subject_of(folder_of.back()));
    }
  }
  for (const auto& n : notes) std::cout << "note: " << n << "\n";
  const lmc::ProcessingCache cache =
      a.no_cache ? lmc::ProcessingCache(fs::path()) : lmc::ProcessingCache::in_user_cache();
  const lmc::CachedBatch batch = lmc::process_folders_cached(jobs, folder_of, options, corrections, cache);
  for (const auto& w : batch.cache_warnings) std::cout << "warning: " << w << "\n";

  lmc::ReviewExportInput exports;
  exports.inputs = a.inputs;
  exports.method = a.method;
  exports.parameters = lmc::process_options_json(options.process);
  lmc::add_length_correction_files(exports.parameters, options.process.method, corrections);
  exports.agreement.motion = a.motion;
  int failed = 0, cached = 0;
  for (size_t k = 0; k < jobs.size(); ++k) {
    const lmc::ProcessedTrial& o = batch.outcomes[k];
    cached += batch.from_cache[k] ? 1 : 0;
    if (!o.ok) {
      std::cerr << jobs[k].trial << ": " << o.error << "\n";
      ++failed;
      continue;
    }
    exports.trials.push_back(lmc::agreement_trial(subjects[k], o.summary));
  }
  if (exports.trials.empty()) throw lmc::Error("no trial could be processed, so there is nothing to draw");
  auto written = lmc::write_review_exports(a.out, exports);

  for (const auto& name : a.trials) {
    bool found = false;
    for (size_t k = 0; k < jobs.size(); ++k) {
      if (jobs[k].trial != name) continue;
      found = true;
      // A trial's series are not cached (only its summary): it is processed again here.
      const lmc::BatchOptions trial_options = lmc::folder_options(options, corrections, folder_of[k]);
      lmc::TrialSeries series = lmc::trial_series(lmc::process_sources_in_full(jobs[k], trial_options));
      series.trial = subjects[k] + "-" + series.trial;
      const nlohmann::json parameters = lmc::process_options_json(trial_options.process);
      for (auto& p :
           lmc::write_trial_export(a.out, series, {jobs[k].lmc.string()}, a.method, parameters, a.each_controller)) {
        written.push_back(std::move(p));
      }
    }
    if (!found) throw lmc::Error("--trial " + name + ": no such trial among the inputs");
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "figures of " << exports.trials.size() << " trial(s) (" << cached << " from the cache, " << failed
            << " failed): " << written.size() << " files in " << a.out << " in " << lmc::format_fixed(seconds, 2)
            << " s\n";
  if (failed > 0) lmc::cli::command_exit_code() = 2;
}

void setup_figures(CLI::App& app) {
  auto a = std::make_shared<FiguresArgs>();
  app.add_option("inputs", a->inputs, "Subject session folders or folders of trials (one subject each)")->required();
  app.add_option("-o,--output", a->out, "Output folder")->required();
  app.add_option("--method", a->method, "Fusion: reference (the study's Kalman filter) or default (our smoother)")
      ->check(CLI::IsMember({"reference", "default"}));
  app.add_option("--motion", a->motion, "Agreement over the trials of one motion only (static, index, thumb, wrist)");
  app.add_option("--trial", a->trials, "Also draw this trial's angles and finger lengths against Vicon (repeatable)");
  app.add_option("--length-correction", a->length_corrections,
                 "FOLDER=FILE: that input's trials with the subject's finger-length correction (lmc length-correction "
                 "fit) after the default fusion, as the Review tab applies it (repeatable)");
  app.add_flag("--each-controller", a->each_controller, "With --trial: each controller's own series too");
  app.add_flag("--no-cache", a->no_cache, "Process every trial again instead of using the processing cache");
  app.callback([a] { run_figures(*a); });
}

const lmc::cli::CommandRegistration figures_command{
    "figures", "The Review tab's tables and figures, headless: agreement, Bland-Altman, visibility map", 46,
    setup_figures};

}  // namespace
