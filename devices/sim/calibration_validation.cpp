#include "devices/sim/calibration_validation.h"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "core/common/number_format.h"
#include "devices/sim/sim_rig.h"

namespace lmc::devices {
namespace {

// The simulated trial as a recording (rows in time order) and its truth on the 100 Hz grid.
struct RecordedSim {
  LmcRecording recording;
  HandTrack truth;
  std::vector<RigidTransform> true_transforms;
  std::int64_t clock_at_truth_zero_us = 0;
};

RecordedSim record(const Layout& layout, const SimConfig& config, double seconds) {
  RecordedSim out;
  const SimTrial trial = generate_sim_trial(layout, config, seconds);
  out.recording.kind = RecordingKind::kRaw;
  out.recording.source = "simulated trial (seed " + std::to_string(config.seed) + ")";
  for (const auto& e : trial.events)
    if (e.is_frame) out.recording.rows.push_back(e.frame.frame);
  out.truth = HandTrack(static_cast<int>(trial.truth.size()));
  for (size_t f = 0; f < trial.truth.size(); ++f)
    for (int p = 0; p < kNumHandPoints; ++p) out.truth.at(static_cast<int>(f), p) = trial.truth[f].point(p);
  const SimRig rig(layout, config);  // same layout and seed: the same devices as the trial's
  for (int d = 0; d < layout.device_count(); ++d) {
    const Eigen::Isometry3d t = rig.true_device_to_world(d);
    out.true_transforms.push_back({t.linear(), t.translation()});
  }
  out.clock_at_truth_zero_us = config.device_clock_start_us;
  return out;
}

CalibrationInput input_of(const RecordedSim& sim, bool with_vicon) {
  InputOptions options;
  options.resample.grid_start_us = sim.clock_at_truth_zero_us;
  return prepare_calibration_input(sim.recording, with_vicon ? &sim.truth : nullptr, options);
}

// Over the controllers `scored` (all when null).
void worst_error(const std::vector<RigidTransform>& got, const std::vector<RigidTransform>& want, double& mm,
                 double& deg, const CalibrationResult* scored = nullptr) {
  mm = deg = 0;
  for (size_t d = 0; d < got.size(); ++d) {
    if (scored != nullptr && !scored->devices[d].fitted) continue;
    mm = std::max(mm, (got[d].t - want[d].t).norm());
    deg = std::max(deg, rotation_angle_deg(got[d].r.transpose() * want[d].r));
  }
}

std::vector<RigidTransform> fitted(const CalibrationResult& r) {
  std::vector<RigidTransform> out;
  for (const auto& d : r.devices) out.push_back(d.fitted_transform);
  return out;
}

}  // namespace

SimConfig validation_sim_config(std::uint64_t seed, const CalibrationValidationOptions& options) {
  SimConfig c;
  c.seed = seed;
  c.motion = HandMotion::kOpen;
  c.calibration_random_translation_mm = options.max_translation_mm;
  c.calibration_random_rotation_deg = options.max_rotation_deg;
  return c;
}

CalibrationValidationCase run_calibration_case(const Layout& layout, std::uint64_t seed,
                                               const CalibrationValidationOptions& options) {
  return run_calibration_case(layout, validation_sim_config(seed, options), options);
}

CalibrationValidationCase run_calibration_case(const Layout& layout, const SimConfig& config,
                                               const CalibrationValidationOptions& options) {
  CalibrationValidationCase c;
  c.seed = config.seed;
  const RecordedSim sim = record(layout, config, options.seconds);
  std::vector<RigidTransform> nominal;
  for (const auto& d : layout.devices) nominal.push_back(device_transform(d));
  worst_error(nominal, sim.true_transforms, c.injected_mm, c.injected_deg);

  const auto vicon_input = input_of(sim, true);
  auto t0 = std::chrono::steady_clock::now();
  const auto with = calibrate(vicon_input, layout);
  c.vicon_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  worst_error(fitted(with), sim.true_transforms, c.vicon_mm, c.vicon_deg, &with);

  // The same grid and labels, Vicon ignored.
  CalibrationOptions no_vicon;
  no_vicon.use_vicon = false;
  t0 = std::chrono::steady_clock::now();
  const auto without = calibrate(vicon_input, layout, no_vicon);
  c.consensus_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Without Vicon only the controllers' relative placement is known: compare with the truth
  // under the same anchoring (consensus_fit.h).
  // Anchored over the controllers the fit anchored (a controller without samples takes no part).
  std::vector<bool> fitted_set;
  for (const auto& d : without.devices) fitted_set.push_back(d.fitted);
  const auto anchored_fitted = anchor_to_nominal(sim.true_transforms, nominal, fitted_set);
  worst_error(fitted(without), anchored_fitted, c.consensus_mm, c.consensus_deg, &without);
  for (const auto& d : with.devices) c.vicon_unfitted += d.fitted ? 0 : 1;
  for (const auto& d : without.devices) c.consensus_unfitted += d.fitted ? 0 : 1;

  c.vicon_ok = c.vicon_mm <= options.vicon_limit_mm && c.vicon_deg <= options.vicon_limit_deg;
  c.consensus_ok = c.consensus_mm <= options.consensus_limit_mm && c.consensus_deg <= options.consensus_limit_deg;
  for (const auto& w : with.all_warnings()) c.warnings.push_back("with Vicon: " + w);
  for (const auto& w : without.all_warnings()) c.warnings.push_back("without Vicon: " + w);
  return c;
}

std::vector<std::string> swapped_serial_warnings(const Layout& layout, int slot_a, int slot_b, std::uint64_t seed,
                                                 bool with_vicon) {
  CalibrationValidationOptions options;
  options.max_translation_mm = 0;
  options.max_rotation_deg = 0;
  options.seconds = 5.0;
  const RecordedSim sim = record(layout, validation_sim_config(seed, options), options.seconds);
  Layout swapped = layout;
  std::swap(swapped.devices[static_cast<size_t>(slot_a)].pose, swapped.devices[static_cast<size_t>(slot_b)].pose);
  std::swap(swapped.devices[static_cast<size_t>(slot_a)].offset_mm,
            swapped.devices[static_cast<size_t>(slot_b)].offset_mm);
  return calibrate(input_of(sim, with_vicon), swapped).warnings;
}

std::string validation_table(const std::vector<CalibrationValidationCase>& cases,
                             const CalibrationValidationOptions& options) {
  std::ostringstream o;
  o << "| seed | injected mm | injected ° | Vicon: left mm | left ° | no Vicon: left mm | left ° | ms (Vicon / none) "
       "|\n";
  o << "|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  CalibrationValidationCase worst;
  int vicon_ok = 0, consensus_ok = 0;
  double slowest = 0;
  int unfitted = 0, unfitted_cases = 0;
  for (const auto& c : cases) {
    o << "| " << c.seed << " | " << format_fixed(c.injected_mm, 1) << " | " << format_fixed(c.injected_deg, 2) << " | "
      << format_fixed(c.vicon_mm, 2) << " | " << format_fixed(c.vicon_deg, 3) << " | "
      << format_fixed(c.consensus_mm, 2) << " | " << format_fixed(c.consensus_deg, 3) << " | "
      << format_fixed(c.vicon_seconds * 1000, 1) << " / " << format_fixed(c.consensus_seconds * 1000, 1) << " |\n";
    worst.vicon_mm = std::max(worst.vicon_mm, c.vicon_mm);
    worst.vicon_deg = std::max(worst.vicon_deg, c.vicon_deg);
    worst.consensus_mm = std::max(worst.consensus_mm, c.consensus_mm);
    worst.consensus_deg = std::max(worst.consensus_deg, c.consensus_deg);
    slowest = std::max({slowest, c.vicon_seconds, c.consensus_seconds});
    unfitted += c.vicon_unfitted;
    unfitted_cases += c.vicon_unfitted > 0 ? 1 : 0;
    vicon_ok += c.vicon_ok ? 1 : 0;
    consensus_ok += c.consensus_ok ? 1 : 0;
  }
  o << "\nWith Vicon: " << vicon_ok << " of " << cases.size() << " cases within "
    << format_fixed(options.vicon_limit_mm, 1) << " mm and " << format_fixed(options.vicon_limit_deg, 1) << "° (worst "
    << format_fixed(worst.vicon_mm, 2) << " mm, " << format_fixed(worst.vicon_deg, 3)
    << "°). Without Vicon: " << consensus_ok << " of " << cases.size() << " within "
    << format_fixed(options.consensus_limit_mm, 1) << " mm and " << format_fixed(options.consensus_limit_deg, 1)
    << "° (worst " << format_fixed(worst.consensus_mm, 2) << " mm, " << format_fixed(worst.consensus_deg, 3)
    << "°). Slowest calibration " << format_fixed(slowest * 1000, 1) << " ms. " << unfitted << " controller(s) in "
    << unfitted_cases
    << " case(s) never saw the hand (their injected error moved it out of view): left as they were with a warning, not "
       "scored.\n";
  return o.str();
}

}  // namespace lmc::devices
