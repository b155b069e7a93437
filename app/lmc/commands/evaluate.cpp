// lmc evaluate: the placement metric and coverage of a fixed layout on a pose set, for all frames
// and split by hand orientation (horizontal / vertical) — the same summary `lmc optimize` prints.
#include <chrono>
#include <iostream>
#include <optional>
#include <string>

#include "app/lmc/command.h"
#include "core/io/pose_source.h"
#include "core/io/layout_json.h"
#include "core/metric/coverage.h"
#include "core/metric/coverage_report.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"

namespace {

struct EvaluateOptions {
  std::string layout;
  std::string poses = "mc";
  int frames = lmc::kDefaultMonteCarloFrames;
  std::uint64_t seed = lmc::kDefaultMonteCarloSeed;
  std::string hand;
  double range_mm = 0;  // 0: the layout's own sensor model
  double radius_mm = 10.0;
  bool json = false;
};

void setup_evaluate(CLI::App& app) {
  auto opt = std::make_shared<EvaluateOptions>();
  app.add_option("--layout", opt->layout, "Layout file or preset name (paper-initial, paper-optimized, …)")->required();
  app.add_option("--poses", opt->poses, "\"mc\" (Monte Carlo set) or a pose-set file from `lmc poses`");
  app.add_option("--frames", opt->frames, "Frames of the Monte Carlo set")->check(CLI::Range(1, 10'000'000));
  app.add_option("--seed", opt->seed, "Seed of the Monte Carlo set");
  app.add_option("--hand", opt->hand, "Monte Carlo set with the hand of this LMC recording's first row");
  app.add_option("--range-mm", opt->range_mm, "Override the layout's sensor range (mm)")->check(CLI::PositiveNumber);
  app.add_option("--radius-mm", opt->radius_mm, "Phalanx radius (mm)")->check(CLI::NonNegativeNumber);
  app.add_flag("--json", opt->json, "Print JSON (keys: see core/metric/coverage_report.h) instead of text");
  app.callback([opt] {
    lmc::Layout layout = lmc::load_layout_or_preset(opt->layout);
    if (opt->range_mm > 0) layout.sensor.range_mm = opt->range_mm;
    const auto hand = opt->hand.empty() ? std::nullopt : std::optional<std::string>(opt->hand);
    const lmc::PoseSet poses = lmc::load_poses(opt->poses, opt->frames, opt->seed, hand);
    const auto t0 = std::chrono::steady_clock::now();
    const auto prepared = lmc::prepare_frames(poses.frames);
    const lmc::VisibilityTable table = lmc::compute_visibility(layout, prepared, opt->radius_mm);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::vector<std::string> slots;
    for (const auto& d : layout.devices) slots.push_back(d.slot);
    const auto all = lmc::compute_coverage(table);
    const auto horizontal_idx = poses.indices_with(lmc::HandOrientation::kHorizontal);
    const auto vertical_idx = poses.indices_with(lmc::HandOrientation::kVertical);
    // An empty subset means "all frames" to compute_coverage; report an empty split as such.
    auto split = [&](const std::vector<int>& idx) {
      if (idx.empty()) {
        lmc::Coverage c;
        c.devices = table.devices;
        c.c.assign(static_cast<size_t>(table.devices) + 1, 0);
        c.device_finger_seen.assign(static_cast<size_t>(table.devices), {});
        return c;
      }
      return lmc::compute_coverage(table, idx);
    };
    const auto horizontal = split(horizontal_idx);
    const auto vertical = split(vertical_idx);
    if (opt->json) {
      nlohmann::json j;
      j["layout"] = layout.name;
      j["poses"] = poses.description;
      j["range_mm"] = layout.sensor.range_mm;
      j["phalanx_radius_mm"] = opt->radius_mm;
      j["all"] = lmc::coverage_to_json(all, slots);
      j["horizontal"] = lmc::coverage_to_json(horizontal, slots);
      j["vertical"] = lmc::coverage_to_json(vertical, slots);
      j["seconds"] = seconds;
      std::cout << j.dump(2) << "\n";
      return;
    }
    std::cout << "layout " << layout.name << " on " << poses.description << " (range " << layout.sensor.range_mm
              << " mm, FOV " << layout.sensor.fov_long_deg << "°×" << layout.sensor.fov_short_deg << "°, radius "
              << opt->radius_mm << " mm)\n";
    std::cout << "all frames:\n" << lmc::format_coverage(all, slots);
    std::cout << "horizontal poses:\n" << lmc::format_coverage(horizontal, slots);
    std::cout << "vertical poses:\n" << lmc::format_coverage(vertical, slots);
    const double evals = static_cast<double>(table.devices) * static_cast<double>(table.frames);
    std::cout << "time " << seconds << " s (" << (seconds > 0 ? evals / seconds : 0.0)
              << " device-frame evaluations/s incl. frame preparation)\n";
  });
}

const lmc::cli::CommandRegistration evaluate_command{
    "evaluate", "Placement metric and coverage of a layout on a pose set", 51, setup_evaluate};

}  // namespace
