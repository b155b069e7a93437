// lmc process — recorded trials through the pipeline: resample, visibility labels,
// realign, fuse (reference = the study's Kalman filter, default = our smoother), measures, and the
// comparison with Vicon. Per trial it writes fused points, per-frame measures, a summary JSON and
// a text report laid out like the authors' result file.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/io/atomic_write.h"
#include "core/processing/batch.h"
#include "core/processing/length_correction_json.h"
#include "core/processing/method_comparison.h"
#include "core/results/batch_outputs.h"
#include "core/session/session_trials.h"
#include "devices/host_memory.h"

namespace {

struct ProcessArgs {
  std::string input;
  std::string vicon;
  std::string layout;
  std::string method = "default";
  std::string mapping;
  std::string out;
  std::string length_correction;
  double max_gap_ms = 50.0;
  bool fixed_gap = false;
  bool compare_methods = false;
  bool quiet = false;
};

// The batch's settings from the command line; a length correction is read (and named on
// stdout) here, before any trial runs.
lmc::BatchOptions batch_options_from_args(const ProcessArgs& a) {
  lmc::BatchOptions options;
  options.process.method = lmc::fusion_method_from_name(a.method);
  if (!a.length_correction.empty()) {
    // Refused here, before any trial runs, rather than once per trial by process_trial.
    if (options.process.method == lmc::FusionMethod::kReference) {
      throw lmc::Error(
          "--length-correction applies to the default fusion only: the reference method stays the study's algorithm");
    }
    if (a.compare_methods)
      throw lmc::Error("--compare-methods runs the reference method too: use it without --length-correction");
    options.process.length_correction = lmc::read_length_correction(a.length_correction);
    const auto& c = *options.process.length_correction;
    std::cout << "length correction of subject " << c.subject << " (fitted on " << c.fit_trial << ", "
              << lmc::length_source_name(c.source) << "): factors";
    for (const double k : c.factor) std::cout << " " << lmc::format_fixed(k, 3);
    std::cout << " (thumb … pinky)\n";
  }
  options.process.resample.max_gap_ms = a.max_gap_ms;
  options.process.resample.adaptive_gap = !a.fixed_gap;
  if (!a.layout.empty()) options.layout = a.layout;
  if (!a.mapping.empty()) options.mapping = a.mapping;
  options.compare_methods = a.compare_methods;
  return options;
}

// A processed trial's line: frames, layout, Vicon and a clear wrist lag, then its warnings.
void print_processed_trial(const lmc::ProcessedTrial& o) {
  std::cout << "ok      " << o.trial << "  (" << o.summary["frames"].get<int>() << " frames, layout " << o.layout_used
            << (o.has_vicon ? ", with Vicon" : ", no Vicon");
  if (o.summary.contains("comparison")) {
    const auto& lag = o.summary["comparison"]["lag"];
    if (lag.value("clear", false) && lag.value("frames", 0) != 0) {
      std::cout << ", wrist lag " << lag["frames"].get<int>()
                << " frame(s) (r = " << lmc::format_fixed(lag["correlation"].get<double>(), 2) << ")";
    }
  }
  std::cout << ")\n";
  for (const auto& w : o.warnings) std::cout << "        warning: " << w << "\n";
}

void run_process(const ProcessArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  lmc::devices::keep_freed_memory_for_reuse();
  const lmc::BatchOptions options = batch_options_from_args(a);

  std::vector<std::string> notes;
  const std::optional<std::filesystem::path> vicon =
      a.vicon.empty() ? std::nullopt : std::optional<std::filesystem::path>(a.vicon);
  const auto jobs = lmc::trial_sources_for_input(a.input, vicon, &notes);
  for (const auto& n : notes) std::cout << "note: " << n << "\n";

  const auto outcomes = lmc::process_and_write_batch(jobs, options, a.out);

  int failed = 0;
  lmc::MethodErrors ref_errors, def_errors;
  int compared = 0;
  nlohmann::json session = nlohmann::json::object();
  session["format"] = "lmc-process-session";
  session["method"] = a.method;
  // Through std::filesystem::path: on Windows an argument arrives in the ANSI code page and the
  // path gives it back as UTF-8, which JSON requires (on Linux it is unchanged).
  if (!a.length_correction.empty())
    session["length_correction_file"] = std::filesystem::path(a.length_correction).string();
  session["input"] = std::filesystem::path(a.input).string();
  session["trials"] = nlohmann::json::array();
  for (size_t k = 0; k < outcomes.size(); ++k) {
    const auto& o = outcomes[k];
    nlohmann::json t{{"trial", o.trial}, {"ok", o.ok}, {"lmc_file", jobs[k].lmc.string()}};
    if (o.ok) {
      t["summary_file"] = o.trial + ".summary.json";
      t["layout"] = o.layout_used;
      t["warnings"] = o.warnings;
      if (!a.quiet) print_processed_trial(o);
      if (a.compare_methods && o.has_vicon) {
        ref_errors.merge(o.reference_errors);
        def_errors.merge(o.default_errors);
        ++compared;
      }
    } else {
      ++failed;
      t["error"] = o.error;
      std::cout << "FAILED  " << o.trial << ": " << o.error << "\n";
    }
    session["trials"].push_back(t);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  session["seconds"] = seconds;
  lmc::write_file_atomically(std::filesystem::path(a.out) / "session.json", session.dump(2) + "\n");
  if (a.compare_methods) {
    const std::string table = lmc::method_comparison_markdown(ref_errors, def_errors, compared);
    lmc::write_file_atomically(std::filesystem::path(a.out) / "method_comparison.md", table);
    std::cout << "\n" << table << "\n";
  }
  std::cout << "processed " << outcomes.size() - static_cast<size_t>(failed) << " of " << outcomes.size()
            << " trial(s) (" << a.method << " method) in " << lmc::format_fixed(seconds, 3) << " s; outputs in "
            << a.out << "\n";
  if (failed > 0) lmc::cli::command_exit_code() = 2;
}

void setup_process(CLI::App& app) {
  auto a = std::make_shared<ProcessArgs>();
  app.add_option("input", a->input, "A trial recording (raw or resampled LMC file) or a session folder")->required();
  app.add_option("--vicon", a->vicon,
                 "Vicon file (.trc/.c3d) for one trial, or a folder of them (default: next to the input)");
  app.add_option("--layout", a->layout,
                 "Layout preset or file (default: the recorder's sidecar, else paper-initial for Naiv_ trials and "
                 "paper-optimized-as-processed for Opti_ trials)");
  app.add_option("--method", a->method, "Fusion: reference (the study's Kalman filter) or default (our smoother)")
      ->check(CLI::IsMember({"reference", "default"}));
  app.add_option("--mapping", a->mapping, "Vicon → LMC point mapping (default assets/mappings/vicon-26-to-lmc.json)");
  app.add_option("--max-gap-ms", a->max_gap_ms,
                 "Longest gap the resampler interpolates across; raised per device to 2.5× its median frame "
                 "interval (a controller at 13 Hz normally has 77 ms between frames) unless --fixed-gap")
      ->check(CLI::PositiveNumber);
  app.add_flag("--fixed-gap", a->fixed_gap, "Use --max-gap-ms as it is for every device");
  app.add_flag("--compare-methods", a->compare_methods,
               "Also run the other method and print both methods' RMSE against the Vicon/truth files");
  app.add_option("--length-correction", a->length_correction,
                 "Apply a subject's finger-length correction (lmc length-correction fit) after the default fusion; off "
                 "unless given");
  app.add_flag("-q,--quiet", a->quiet, "Only failures and the final line");
  app.add_option("-o,--output", a->out, "Output folder")->required();
  app.callback([a] { run_process(*a); });
}

const lmc::cli::CommandRegistration process_command{
    "process", "Process recorded trials: fuse, measure, compare with Vicon", 40, setup_process};

}  // namespace
