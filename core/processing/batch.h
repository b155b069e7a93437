#pragma once
// A session folder (or one trial) through the pipeline, for `lmc process` and the workbench.
// Trials are found by file name (trial_tag.h): LMC files `LMC_<trial>.raw.txt`,
// `Interp_LMC_<trial>.txt`, `<…>.resampled.txt`, `<…>.raytraced.txt` (a raw file wins when a
// trial has several), Vicon files `<trial>.trc` or `<trial>.c3d` in the same folder, and the
// recorder's sidecar `LMC_<trial>.session.json` (its layout is used unless one is given).
// Trials run in parallel (oneTBB), each on its own; a trial that fails gives a message and the
// others still run. Results come back in trial-name order whatever the thread count.
#include <filesystem>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/vicon_mapping.h"
#include "core/processing/method_comparison.h"
#include "core/processing/trial_pipeline.h"

namespace lmc {

struct TrialSources {
  std::string trial;
  std::filesystem::path lmc;
  std::optional<std::filesystem::path> vicon;
  std::optional<std::filesystem::path> sidecar;
  // The layout the trial was recorded with, when its folder knows it (a subject session's
  // manifest); used when neither --layout nor a sidecar gives one.
  std::optional<nlohmann::json> layout_json;
};

// `input` is an LMC file or a folder. `vicon` (optional) is a Vicon file (single trial) or a
// folder to look in. Notes: files that look like trials but were skipped, and why.
std::vector<TrialSources> discover_trials(const std::filesystem::path& input,
                                          const std::optional<std::filesystem::path>& vicon,
                                          std::vector<std::string>* notes = nullptr);

// Vicon markers from .trc or .c3d, in mm; throws lmc::Error naming the file.
MarkerSeries load_vicon_markers(const std::filesystem::path& path);

struct BatchOptions {
  ProcessOptions process;
  std::optional<std::string> layout;  // name or path; else sidecar, else by trial tag
  std::optional<std::filesystem::path> mapping;
  // Called with each trial's whole result and its summary (trial_summary_json, built once for the
  // outcome) as soon as it is processed (from the worker threads, so it must be thread-safe):
  // `lmc process` writes the trial's files there (core/results), which processing itself knows
  // nothing of.
  std::function<void(const TrialAnalysis&, const nlohmann::json& summary)> on_result;
  bool compare_methods = false;  // also run the other method and collect errors vs truth
  // The workbench runs a batch on a worker thread: once `stop` is requested, trials not yet
  // started are left out (outcome "cancelled"); the ones running finish (a trial takes well under a
  // second). `on_progress(done, total)` is called after each trial, from the worker threads.
  std::stop_token stop;
  std::function<void(int done, int total)> on_progress;
};

struct ProcessedTrial {
  std::string trial;
  bool ok = false;
  std::string error;  // when !ok
  std::vector<std::string> warnings;
  nlohmann::json summary;  // trial_summary_json (ok only)
  std::string layout_used;
  bool has_vicon = false;
  // compare_methods: errors of both methods against Vicon/truth.
  MethodErrors reference_errors, default_errors;
  bool cancelled = false;  // left out because the batch was stopped (ok is false)
};

// The layout for a trial: explicit name/path; else the sidecar's; else paper-initial for "Naiv"
// trials and paper-optimized-as-processed for "Opti" ones (reproduces the authors' processing).
Layout resolve_layout(const TrialSources& job, const std::optional<std::string>& layout, std::string* used);

ProcessedTrial process_sources(const TrialSources& job, const BatchOptions& options, const ViconMapping& mapping);

// One trial with every intermediate kept (the Review tab's trial view, `lmc figures --trial`):
// process_sources with options.mapping (or the default mapping) and without the method comparison.
// `outcome` (optional) receives the summary and warnings. Throws lmc::Error naming the trial.
TrialAnalysis process_sources_in_full(const TrialSources& job, const BatchOptions& options,
                                      ProcessedTrial* outcome = nullptr);
std::vector<ProcessedTrial> process_batch(const std::vector<TrialSources>& jobs, const BatchOptions& options);

}  // namespace lmc
