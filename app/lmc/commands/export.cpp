// lmc export c3d|trc TRIAL… -o DIR: each processed trial as a C3D or TRC point file for
// motion-analysis tools (OpenSim, Visual3D, Mokka). Which points, their labels, the axes and
// missing data are core/export/trial_points.h's rules (docs/export.md); this file parses options
// and prints. lmc export bids SESSION_OR_STUDY… -o DATASET: the study as a BIDS-motion dataset
// (core/export/bids_dataset.h).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/export/bids_dataset.h"
#include "core/export/trial_points.h"
#include "core/processing/length_correction_json.h"

namespace {

struct ExportArgs {
  std::vector<std::string> inputs;
  std::string out;
  std::string method = "default";
  std::string length_correction;
  std::string layout;
  std::string axes = "world";
  bool force = false;
};

constexpr const char* kExportFooter =
    "Writes DIR/<trial>.c3d (or .trc) per trial: the whole processed trial at the processing rate (100 Hz), "
    "units mm. Labels: F_<landmark> the fused hand; LMC<n>_<landmark> controller n's hand realigned into the world "
    "frame; V_<marker> the trial's Vicon markers (when <trial>.trc/.c3d is next to the recording; Vicon frame f is "
    "grid frame f, as Review aligns them). Landmarks (28 per hand): Palm, Elbow, Wrist, "
    "<Thumb|Index|Middle|Ring|Pinky>_<Meta|Proxi|Inter|Dist|End> (Proxi = MCP joint; the thumb's Meta equals its "
    "Proxi). Axes: world = x along the table, y up (table top y = 0), z towards the subject; opensim = X forward "
    "from the subject (-z), Y up (y), Z to the subject's right (x). Missing points: C3D residual -1, TRC empty "
    "cells. An existing output is refused unless --force. Trials that cannot be exported are left out with a "
    "note (exit code 2). See docs/export.md.";

constexpr const char* kBidsFooter =
    "Writes a BIDS-motion dataset (BIDS 1.9): one subject per session folder (sub-<id>, or sub-01, sub-02, ... with "
    "--anonymise KEYFILE, the key kept outside the dataset), each accepted trial as "
    "sub-<id>/motion/sub-<id>_task-<motion>_tracksys-<system>_acq-<layout>_run-<pose><repetition>_motion.tsv with its "
    "channels.tsv/.json and motion.json, events.tsv (go, stop, Vicon trigger) and the subject's scans.tsv; tracking "
    "systems LMC1... (each controller realigned), LMCfused (the fused hand), Vicon (when the trial has a Vicon file). "
    "Labels keep letters and digits only (S_01 -> sub-S01). Top level: dataset_description.json, "
    "participants.tsv/.json "
    "(handedness, hand length and breadth), README, layouts/ (named in .bidsignore). A non-empty DATASET is refused "
    "unless --force. Trials that cannot be exported are left out with a note (exit code 2). See docs/export.md.";

// Fusion and layout options shared by every export format: as lmc process takes them.
void apply_session_options(const ExportArgs& a, lmc::BatchOptions& session) {
  session.process.method = lmc::fusion_method_from_name(a.method);
  if (!a.length_correction.empty()) {
    // As lmc process: the reference method stays the study's algorithm.
    if (session.process.method == lmc::FusionMethod::kReference) {
      throw lmc::Error(
          "--length-correction applies to the default fusion only: the reference method stays the study's algorithm");
    }
    session.process.length_correction = lmc::read_length_correction(a.length_correction);
  }
  if (!a.layout.empty()) session.layout = a.layout;
}

// The output folder and the fusion options, alike in every export subcommand.
void add_common_options(CLI::App* app, ExportArgs& a) {
  app->add_option("-o,--output", a.out, "Output folder (created when missing)")->required();
  app->add_option("--method", a.method, "Fusion: reference (the study's Kalman filter) or default (our smoother)")
      ->check(CLI::IsMember({"reference", "default"}));
  app->add_option("--length-correction", a.length_correction,
                  "Apply a subject's finger-length correction (lmc length-correction fit) after the default fusion");
  app->add_option("--layout", a.layout, "Layout preset or file (default: as lmc process chooses)");
}

void run_export(const ExportArgs& a, lmc::ExportFormat format) {
  lmc::TrialExportRequest req;
  for (const auto& i : a.inputs) req.inputs.emplace_back(i);
  req.out_dir = a.out;
  req.format = format;
  req.axes = lmc::export_axes_from_name(a.axes);
  req.force = a.force;
  apply_session_options(a, req.session);
  req.on_trial = [](const std::string& line) { std::cout << line << "\n"; };
  const lmc::TrialExportReport report = lmc::export_trials(req);
  for (const auto& n : report.notes) std::cout << "note: " << n << "\n";
  std::cout << "exported " << report.exported.size() << " trial(s) as "
            << (format == lmc::ExportFormat::kC3d ? "C3D" : "TRC") << " (" << lmc::export_axes_name(req.axes)
            << " axes, " << a.method << " method) to " << a.out;
  if (report.left_out > 0) std::cout << "; " << report.left_out << " left out (see the notes)";
  std::cout << "\n";
  if (report.left_out > 0) lmc::cli::command_exit_code() = 2;
}

void add_format(CLI::App& parent, const char* name, const char* what, lmc::ExportFormat format) {
  auto a = std::make_shared<ExportArgs>();
  CLI::App* app = parent.add_subcommand(name, what);
  app->add_option("trials", a->inputs,
                  "Recordings, processed trials (Interp_LMC_…) or session folders, as lmc process takes them")
      ->required();
  add_common_options(app, *a);
  app->add_option("--axes", a->axes, "world (the rig's frame) or opensim (X forward, Y up, Z right)")
      ->check(CLI::IsMember({"world", "opensim"}));
  app->add_flag("--force", a->force, "Replace outputs that exist");
  app->footer(kExportFooter);
  app->callback([a, format] { run_export(*a, format); });
}

struct BidsArgs {
  ExportArgs common;
  std::string anonymise_key;
};

void run_bids(const BidsArgs& a) {
  lmc::BidsExportRequest req;
  for (const auto& i : a.common.inputs) req.inputs.emplace_back(i);
  req.out_dir = a.common.out;
  req.force = a.common.force;
  req.anonymise = !a.anonymise_key.empty();
  req.anonymise_key = a.anonymise_key;
  apply_session_options(a.common, req.session);
  req.on_trial = [](const std::string& line) { std::cout << line << "\n"; };
  const lmc::BidsExportReport report = lmc::export_bids(req);
  for (const auto& n : report.notes) std::cout << "note: " << n << "\n";
  std::cout << "exported " << report.trials << " trial(s) of " << report.subjects << " subject(s) as BIDS-motion ("
            << a.common.method << " method) to " << a.common.out;
  if (req.anonymise) std::cout << "; anonymisation key " << a.anonymise_key;
  if (report.left_out > 0) std::cout << "; " << report.left_out << " left out (see the notes)";
  std::cout << "\n";
  if (report.left_out > 0) lmc::cli::command_exit_code() = 2;
}

void add_bids(CLI::App& parent) {
  auto a = std::make_shared<BidsArgs>();
  CLI::App* app = parent.add_subcommand("bids", "The study as a BIDS-motion dataset (one subject per session folder)");
  app->add_option("sessions", a->common.inputs, "Subject session folders, or study folders holding several")
      ->required();
  add_common_options(app, a->common);
  app->add_option("--anonymise", a->anonymise_key,
                  "Number the subjects sub-01, sub-02, ... and write the key (label -> subject id) to this file, "
                  "outside the dataset");
  app->add_flag("--force", a->common.force,
                "Write into a non-empty dataset folder (an earlier export's subjects are removed first)");
  app->footer(kBidsFooter);
  app->callback([a] { run_bids(*a); });
}

void setup_export(CLI::App& app) {
  add_format(app, "c3d", "Each trial as a C3D file (float storage, mm)", lmc::ExportFormat::kC3d);
  add_format(app, "trc", "Each trial as a TRC 4.0 file (as OpenSim reads it, mm)", lmc::ExportFormat::kTrc);
  add_bids(app);
  app.require_subcommand(1);
  app.footer(kExportFooter);
}

const lmc::cli::CommandRegistration export_command{
    "export", "Export processed trials as C3D or TRC point files or a study as a BIDS-motion dataset", 47,
    setup_export};

}  // namespace
