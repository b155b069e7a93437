// lmc calibrate — refine every controller's device-to-world transform from a short trial of a
// still hand: against the Vicon file when one is given, else against the other
// controllers (core/calibration/). Writes the corrected layout and prints the residual table;
// `--validate-sim N` instead runs N seeded simulated cases with injected errors and prints how
// much of each error is left (devices/sim/calibration_validation.h).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

#include "app/lmc/command.h"
#include "core/calibration/calibrate_trial.h"
#include "core/calibration/calibrated_layout.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/utc_time.h"
#include "core/io/atomic_write.h"
#include "core/io/layout_json.h"
#include "core/processing/batch.h"
#include "core/results/trial_outputs.h"
#include "devices/sim/calibration_validation.h"

namespace {

namespace fs = std::filesystem;

struct CalibrateArgs {
  std::string trial;
  std::string vicon;
  std::string layout;
  std::string mapping;
  std::string out;
  double vicon_delay_ms = 0.0;
  int validate_sim = 0;
  bool anchor_to_layout = false;
};

void run_validation(const CalibrateArgs& a) {
  const lmc::Layout layout = lmc::load_layout_or_preset(a.layout.empty() ? "paper-initial" : a.layout);
  lmc::devices::CalibrationValidationOptions options;
  options.cases = a.validate_sim;
  std::vector<lmc::devices::CalibrationValidationCase> cases;
  int unexpected = 0;
  for (int k = 0; k < options.cases; ++k) {
    cases.push_back(
        lmc::devices::run_calibration_case(layout, options.first_seed + static_cast<std::uint64_t>(k), options));
    for (const auto& w : cases.back().warnings) std::cout << "seed " << cases.back().seed << ": warning: " << w << "\n";
    unexpected += cases.back().vicon_ok && cases.back().consensus_ok ? 0 : 1;
  }
  std::cout << "Layout " << layout.name << ", " << options.cases << " simulated still-hand trials of "
            << lmc::format_fixed(options.seconds, 0) << " s, errors injected per controller up to "
            << lmc::format_fixed(options.max_translation_mm, 0) << " mm and "
            << lmc::format_fixed(options.max_rotation_deg, 0) << "°\n\n"
            << lmc::devices::validation_table(cases, options);
  for (const bool vicon : {true, false}) {
    const auto w = lmc::devices::swapped_serial_warnings(layout, 1, 2, options.first_seed, vicon);
    std::cout << "Serials of slots 2 and 3 swapped, " << (vicon ? "with Vicon: " : "without Vicon: ")
              << (w.empty() ? std::string("NOT detected") : w.front()) << "\n";
    unexpected += w.empty() ? 1 : 0;
  }
  if (unexpected > 0) lmc::cli::command_exit_code() = 2;
}

void run_calibrate(const CalibrateArgs& a) {
  if (a.validate_sim > 0) {
    run_validation(a);
    return;
  }
  if (a.trial.empty()) throw lmc::Error("give a calibration trial (an LMC recording file), or --validate-sim N");
  if (a.layout.empty())
    throw lmc::Error("give --layout: the layout the trial was recorded with (a preset name or a file)");
  if (a.out.empty()) throw lmc::Error("give -o FILE: where to write the calibrated layout");
  const lmc::Layout layout = lmc::load_layout_or_preset(a.layout);
  lmc::TrialCalibrationRequest request;
  request.trial = a.trial;
  if (!a.vicon.empty()) request.vicon = fs::path(a.vicon);
  request.mapping = a.mapping;
  request.vicon_delay_ms = a.vicon_delay_ms;
  request.anchor_to_layout = a.anchor_to_layout;
  request.when_utc = lmc::utc_now_iso8601();
  const lmc::TrialCalibration cal = lmc::calibrate_trial(request, layout);
  for (const auto& w : cal.file_warnings) std::cout << "warning: " << w << "\n";
  for (const auto& n : cal.notes) std::cout << "note: " << n << "\n";
  const lmc::CalibrationResult& result = cal.result;
  std::cout << lmc::residual_table(result);

  const lmc::Layout& out = cal.calibrated;
  lmc::write_file_atomically(a.out, lmc::layout_to_json(out).dump(2) + "\n");
  int fitted = 0;
  for (const auto& d : result.devices) fitted += d.fitted ? 1 : 0;
  std::cout << "wrote " << a.out << " (" << fitted << " of " << result.devices.size() << " controllers calibrated"
            << (result.with_vicon ? ", against Vicon" : ", without Vicon") << ")\n";
  if (!result.all_warnings().empty()) lmc::cli::command_exit_code() = 2;
}

void setup_calibrate(CLI::App& app) {
  auto a = std::make_shared<CalibrateArgs>();
  app.add_option("trial", a->trial,
                 "The calibration trial: an LMC recording (raw or resampled) of a still open hand, 5–10 s");
  app.add_option(
      "--vicon", a->vicon,
      "Vicon file (.trc/.c3d) of the same trial: calibrate against it instead of the controllers' consensus");
  app.add_option("--layout", a->layout, "The layout the trial was recorded with (preset name or file)");
  app.add_option("--mapping", a->mapping, "Vicon → LMC point mapping (default assets/mappings/vicon-26-to-lmc.json)");
  app.add_option("--vicon-delay-ms", a->vicon_delay_ms,
                 "Nexus's trigger Delay (ms), added to the sidecar's Vicon alignment of a real recording");
  app.add_flag(
      "--anchor-to-layout", a->anchor_to_layout,
      "With --vicon: keep the layout's world frame and take only the controllers' placement relative to each other "
      "from Vicon (when the Vicon origin is not the layout's)");
  app.add_option("-o,--output", a->out, "Where to write the calibrated layout (JSON)");
  app.add_option(
         "--validate-sim", a->validate_sim,
         "Instead: run N seeded simulated trials with injected errors (≤ 80 mm, ≤ 10° per controller) and print "
         "how much error calibration leaves (--layout defaults to paper-initial)")
      ->check(CLI::PositiveNumber);
  app.footer(
      "Exit code 2 when the calibration ran but warned (a controller left as it was, an implausible correction, a "
      "residual that stays high, swapped serials).");
  app.callback([a] { run_calibrate(*a); });
}

const lmc::cli::CommandRegistration calibrate_command{
    "calibrate", "Calibrate the controllers from a short trial of a still hand", 42, setup_calibrate};

}  // namespace
