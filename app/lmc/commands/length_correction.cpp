// lmc length-correction fit — a subject's finger-length correction
// (core/processing/length_correction.h): one factor per finger, fitted on one trial of the subject
// processed with the default fusion, against that trial's Vicon (or simulated truth), or against
// the anthropometric fingers of the hand length and breadth typed in. `lmc process
// --length-correction FILE` applies it to the subject's other trials; nothing applies it unasked.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/processing/batch.h"
#include "core/processing/length_correction_json.h"
#include "core/session/session_trials.h"

namespace {

struct LengthFitArgs {
  std::string input, trial, vicon, layout, subject, out;
  double hand_length_mm = 0, hand_breadth_mm = 0;
};

lmc::TrialSources fit_trial_job(const LengthFitArgs& a) {
  const bool single_file = !std::filesystem::is_directory(a.input);
  const std::optional<std::filesystem::path> vicon =
      a.vicon.empty() ? std::nullopt : std::optional<std::filesystem::path>(a.vicon);
  if (vicon && !single_file && !std::filesystem::is_directory(*vicon)) {
    throw lmc::Error("--vicon must be a folder when the input is a folder (or give the trial's LMC file)");
  }
  const auto jobs = lmc::trial_sources_for_input(a.input, vicon);
  if (!a.trial.empty()) {
    for (const auto& j : jobs)
      if (j.trial == a.trial) return j;
    throw lmc::Error(lmc::ErrorLocation(a.input),
                     "no trial '" + a.trial + "' here (" + std::to_string(jobs.size()) + " trial(s) found)");
  }
  if (jobs.size() != 1) {
    throw lmc::Error(
        lmc::ErrorLocation(a.input),
        "holds " + std::to_string(jobs.size()) + " trials: name the one to fit on with --trial (e.g. a static one)");
  }
  return jobs.front();
}

void run_length_fit(const LengthFitArgs& a) {
  const bool from_hand = a.hand_length_mm != 0 || a.hand_breadth_mm != 0;
  if (from_hand && (a.hand_length_mm <= 0 || a.hand_breadth_mm <= 0)) {
    throw lmc::Error("give both --hand-length-mm and --hand-breadth-mm, each a positive length in mm (given " +
                     lmc::format_fixed(a.hand_length_mm, 1) + " and " + lmc::format_fixed(a.hand_breadth_mm, 1) + ")");
  }
  if (from_hand && !a.vicon.empty()) {
    throw lmc::Error(
        "fit either to Vicon (--vicon) or to the hand's dimensions (--hand-length-mm/--hand-breadth-mm), not both");
  }
  const lmc::TrialSources job = fit_trial_job(a);
  if (!from_hand && !job.vicon) {
    throw lmc::Error(lmc::ErrorLocation(job.lmc.string()), "no Vicon file for trial " + job.trial + " (" + job.trial +
                                                               ".trc or .c3d): give --vicon, or fit to "
                                                               "--hand-length-mm and --hand-breadth-mm");
  }

  lmc::BatchOptions so;
  so.process.method = lmc::FusionMethod::kDefault;  // the factors are fitted on what they will correct
  if (!a.layout.empty()) so.layout = a.layout;
  const lmc::TrialAnalysis r = lmc::process_sources_in_full(job, so);

  lmc::LengthCorrection c;
  if (from_hand) {
    c = lmc::fit_length_correction_to_hand(r.lmc_frames, a.hand_length_mm, a.hand_breadth_mm, "trial " + job.trial);
  } else {
    if (!r.has_vicon) throw lmc::Error("trial " + job.trial + ": its Vicon file gave no frames");
    c = lmc::fit_length_correction_to_vicon(r.lmc_frames, r.vicon_frames,
                                            "trial " + job.trial + " with " + job.vicon->string());
    c.fit_vicon_file = job.vicon->string();
  }
  c.subject = a.subject;
  c.fit_trial = job.trial;
  c.fit_lmc_file = job.lmc.string();
  lmc::write_length_correction(a.out, c);

  std::cout << "length correction for subject " << c.subject << " from trial " << c.fit_trial << " ("
            << (from_hand ? "hand " + lmc::format_fixed(a.hand_length_mm, 1) + " × " +
                                lmc::format_fixed(a.hand_breadth_mm, 1) + " mm"
                          : "Vicon " + c.fit_vicon_file)
            << ", " << c.fit_frames << " frames, default fusion)\n";
  std::cout << "  finger     fused mm  target mm  factor\n";
  for (size_t f = 0; f < lmc::kNumFingers; ++f) {
    std::cout << "  " << std::left << std::setw(8) << lmc::digit_name(static_cast<int>(f)) << std::right
              << std::setw(11) << lmc::format_fixed(c.fused_mm[f], 1) << std::setw(11)
              << lmc::format_fixed(c.target_mm[f], 1) << std::setw(8) << lmc::format_fixed(c.factor[f], 3) << "\n";
  }
  std::cout << "written to " << a.out << "; apply with lmc process --length-correction " << a.out
            << " (default method; score it only on trials other than " << c.fit_trial << ")\n";
}

void setup_length_correction(CLI::App& app) {
  app.require_subcommand(1);
  auto a = std::make_shared<LengthFitArgs>();
  CLI::App* fit = app.add_subcommand("fit", "Fit a subject's per-finger length factors on one trial (default fusion)");
  fit->add_option("input", a->input, "The trial's LMC file, or a session folder with --trial")->required();
  fit->add_option("--trial", a->trial, "Which trial of the folder to fit on (one static trial of the subject)");
  fit->add_option("--vicon", a->vicon, "The trial's Vicon file (.trc/.c3d; default: next to the LMC file)");
  fit->add_option(
      "--hand-length-mm", a->hand_length_mm,
      "Fit to the anthropometric fingers of this hand length (wrist crease to middle fingertip) instead of Vicon");
  fit->add_option("--hand-breadth-mm", a->hand_breadth_mm,
                  "The hand's breadth across the knuckles (with --hand-length-mm)");
  fit->add_option("--layout", a->layout, "Layout (name or file); default: the recorder sidecar's, else by trial name");
  fit->add_option("--subject", a->subject, "Subject id written into the file (the trials it is meant for)")->required();
  fit->add_option("-o,--output", a->out, "Correction file to write (JSON)")->required();
  fit->callback([a] { run_length_fit(*a); });
}

const lmc::cli::CommandRegistration length_correction_command{
    "length-correction", "Fit a subject's finger-length correction (optional; default fusion only)", 41,
    setup_length_correction};

}  // namespace
