// lmc optimize: search device placements with the particle swarm of docs/algorithms/search.md
// (core/optimise/pso.h) on a pose set, save the best layout and print the same summary as
// `lmc evaluate`.

#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "core/io/pose_source.h"
#include "core/optimise/multi_start.h"
#include "core/optimise/pso.h"
#include "core/platform/process.h"
#include "core/poses/pose_recipe.h"
#include "core/reports/coverage_report.h"
#include "core/reports/robust_terms_report.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"

namespace {

struct OptimizeOptions {
  std::string poses = "mc";
  int frames = lmc::kDefaultMonteCarloFrames;
  std::uint64_t seed = lmc::kDefaultMonteCarloSeed;
  std::string hand;
  int devices = 4;
  int particles = 30;
  int iterations = 100;
  double w = 0.9, c1 = 0.5, c2 = 0.3;
  std::uint64_t pso_seed = 1;
  int threads = 0;
  std::string bounds;
  double range_mm = 0.0;  // 0: the start layout's own ranges, or the study's 600 mm
  std::string models;     // --models: catalogue ids, one or one per device
  double radius_mm = 10.0;
  std::string start;
  std::vector<std::string> locks;
  std::string output;
  bool json = false;
  bool no_progress = false;
  bool exhaustive = false;
  std::string metric = "robust";
  int starts = 1;
  lmc::RobustWeights weights;
};

void apply_lock(lmc::SearchSpace& space, const lmc::Layout& layout, const std::string& spec) {
  // SLOT or SLOT:param+param (e.g. LMC2 or LMC3:x+z)
  const size_t colon = spec.find(':');
  const std::string slot = spec.substr(0, colon);
  const int d = layout.find_slot(slot);
  if (d < 0) throw lmc::Error(lmc::ErrorLocation("--lock"), "no device with slot \"" + slot + "\" in the start layout");
  if (colon == std::string::npos) {
    space.lock_device(d);
    return;
  }
  std::string rest = spec.substr(colon + 1);
  size_t start = 0;
  while (start <= rest.size()) {
    const size_t plus = rest.find('+', start);
    const std::string name = rest.substr(start, plus == std::string::npos ? std::string::npos : plus - start);
    const int k = lmc::pose_param_from_name(name.c_str());
    if (k < 0) throw lmc::Error(lmc::ErrorLocation("--lock"), "unknown parameter \"" + name + "\" in \"" + spec + "\"");
    space.lock_param(d, k);
    if (plus == std::string::npos) break;
    start = plus + 1;
  }
}

// The layout the swarm starts from: --start's devices, else the default rig of --devices; then
// the sensor models and range asked for.
lmc::Layout optimize_start_layout(const OptimizeOptions& opt) {
  lmc::Layout start =
      opt.start.empty() ? lmc::default_start_layout(opt.devices) : lmc::load_layout_or_preset(opt.start);
  if (!opt.models.empty()) lmc::set_models_from_list(start, opt.models, lmc::sensor_catalogue());
  if (opt.range_mm > 0) {
    for (auto& d : start.devices) d.sensor.range_mm = opt.range_mm;
  }
  return start;
}

lmc::SearchSpace optimize_search_space(const OptimizeOptions& opt, const lmc::Layout& start) {
  // The study's metric searches the authors' box (the reference); the robust one the table.
  const lmc::SearchSpace default_space = opt.metric == "study" ? lmc::SearchSpace{} : lmc::table_search_space();
  lmc::SearchSpace space = opt.bounds.empty() ? default_space : lmc::parse_search_bounds(opt.bounds);
  for (const auto& l : opt.locks) apply_lock(space, start, l);
  if (opt.start.empty() && !opt.locks.empty()) throw lmc::Error("--lock needs --start");
  return space;
}

lmc::PsoSettings pso_settings(const OptimizeOptions& opt) {
  lmc::PsoSettings s;
  s.particles = opt.particles;
  s.iterations = opt.iterations;
  s.w = opt.w;
  s.c1 = opt.c1;
  s.c2 = opt.c2;
  s.seed = opt.pso_seed;
  s.threads = opt.threads;
  s.start_from_layout = !opt.start.empty();
  s.phalanx_radius_mm = opt.radius_mm;
  s.metric = lmc::placement_metric_from_name(opt.metric, "--metric");
  s.weights = opt.weights;
  if (opt.exhaustive) s.prune_round_frames = 0;
  return s;
}

// A bar on stderr when it is a terminal (and --no-progress was not given): start, iteration, best cost.
std::function<void(const lmc::MultiStartProgress&)> optimize_progress_bar(bool bar, const char* cost_name) {
  return [bar, cost_name](const lmc::MultiStartProgress& m) {
    if (!bar) return;
    const lmc::PsoProgress& p = m.pso;
    const int width = 30;
    const int filled = p.iterations > 0 ? p.iteration * width / p.iterations : width;
    std::fprintf(stderr, "\rstart %d/%d [%s%s] %d/%d  best %s %.6g  %lld evaluations", m.start + 1, m.starts,
                 std::string(static_cast<size_t>(filled), '#').c_str(),
                 std::string(static_cast<size_t>(width - filled), ' ').c_str(), p.iteration, p.iterations, cost_name,
                 p.best_cost, static_cast<long long>(p.device_frame_evaluations));
    if (p.iteration == p.iterations) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  };
}

// The effort of every start together.
struct SearchEffort {
  double seconds = 0;
  std::int64_t layout_evaluations = 0, device_frame_evaluations = 0, layouts_stopped_early = 0;
  double rate() const { return seconds > 0 ? static_cast<double>(device_frame_evaluations) / seconds : 0.0; }
};

SearchEffort search_effort(const lmc::MultiStartResult& multi) {
  SearchEffort e;
  for (const auto& run : multi.runs) {
    e.seconds += run.seconds;
    e.layout_evaluations += run.layout_evaluations;
    e.device_frame_evaluations += run.device_frame_evaluations;
    e.layouts_stopped_early += run.layouts_stopped_early;
  }
  return e;
}

void print_search_json(const OptimizeOptions& opt, const lmc::MultiStartResult& multi, const lmc::Layout& best,
                       const std::vector<std::string>& slots, const lmc::RobustWeights& weights) {
  const lmc::PsoResult& r = multi.runs.at(static_cast<size_t>(multi.best));
  const SearchEffort effort = search_effort(multi);
  nlohmann::json j;
  j["status"] = r.status == lmc::JobStatus::kCompleted ? "completed" : "cancelled";
  j["metric"] = opt.metric;
  j["layout"] = lmc::layout_to_json(best);
  j["summary"] = lmc::coverage_to_json(r.best_coverage, slots);
  j["robust_terms"] = lmc::robust_terms_to_json(r.best_terms, weights);
  j["best_cost_history"] = r.best_cost_history;
  nlohmann::json starts = nlohmann::json::array();
  for (size_t k = 0; k < multi.runs.size(); ++k) {
    starts.push_back({{"seed", multi.seeds[k]},
                      {"best_cost", multi.runs[k].best_cost},
                      {"best_cost_history", multi.runs[k].best_cost_history},
                      {"layout", lmc::layout_to_json(multi.runs[k].best_layout)}});
  }
  j["starts"] = starts;
  j["best_start"] = multi.best;
  j["runners_up"] = multi.runners_up;
  j["seconds"] = effort.seconds;
  j["layout_evaluations"] = effort.layout_evaluations;
  j["device_frame_evaluations"] = effort.device_frame_evaluations;
  j["layouts_stopped_early"] = effort.layouts_stopped_early;
  j["device_frame_evaluations_per_second"] = effort.rate();
  std::cout << j.dump(2) << "\n";
}

void print_search_text(const OptimizeOptions& opt, const lmc::MultiStartResult& multi, const lmc::Layout& best,
                       const std::vector<std::string>& slots, const lmc::RobustWeights& weights,
                       const std::string& poses_description, const char* cost_name) {
  const lmc::PsoResult& r = multi.runs.at(static_cast<size_t>(multi.best));
  const SearchEffort effort = search_effort(multi);
  std::cout << "best layout (" << opt.output << "):\n";
  for (const auto& d : best.devices) {
    std::printf("  %-6s x %8.2f  y %8.2f  z %8.2f  rx %7.2f  ry %7.2f  rz %7.2f\n", d.slot.c_str(), d.pose.x_mm,
                d.pose.y_mm, d.pose.z_mm, d.pose.rx_deg, d.pose.ry_deg, d.pose.rz_deg);
  }
  std::fflush(stdout);
  std::cout << "on " << poses_description << ":\n" << lmc::format_coverage(r.best_coverage, slots);
  std::cout << lmc::format_robust_terms(r.best_terms, weights);
  if (multi.runs.size() > 1) {
    std::cout << "starts (best first):\n";
    std::printf("  seed %llu  %s %.6g  (best)\n",
                static_cast<unsigned long long>(multi.seeds[static_cast<size_t>(multi.best)]), cost_name, r.best_cost);
    for (const int k : multi.runners_up) {
      std::printf("  seed %llu  %s %.6g  (a different layout)\n",
                  static_cast<unsigned long long>(multi.seeds[static_cast<size_t>(k)]), cost_name,
                  multi.runs[static_cast<size_t>(k)].best_cost);
    }
  }
  std::cout << "time " << effort.seconds << " s, " << effort.layout_evaluations << " layout evaluations ("
            << effort.layouts_stopped_early << " stopped early: they could no longer beat their own best), "
            << effort.device_frame_evaluations << " device-frame evaluations (" << effort.rate() << " per second)\n";
}

void run_optimize(const OptimizeOptions& opt) {
  if (const std::string problem = lmc::kernel_setting_problem(); !problem.empty()) {
    std::cerr << "lmc optimize: " << problem << "\n";
  }
  const lmc::Layout start = optimize_start_layout(opt);
  const lmc::SearchSpace space = optimize_search_space(opt, start);

  const auto hand = opt.hand.empty() ? std::nullopt : std::optional<std::string>(opt.hand);
  std::vector<std::string> notes;
  const lmc::PoseSet poses = lmc::load_pose_spec(opt.poses, opt.frames, opt.seed, hand, &notes);
  for (const auto& n : notes) std::cerr << "lmc: note: left out of the pose set: " << n << "\n";
  const auto prepared = lmc::prepare_frames(poses.frames);

  const lmc::PsoSettings s = pso_settings(opt);
  const char* cost_name = s.metric == lmc::PlacementMetricKind::kStudy ? "M" : "R";
  const bool bar = !opt.no_progress && lmc::platform::stderr_is_terminal();
  const lmc::MultiStartResult multi =
      lmc::run_multi_start(start, space, prepared, s, opt.starts, optimize_progress_bar(bar, cost_name));
  const lmc::PsoResult& r = multi.runs.at(static_cast<size_t>(multi.best));
  lmc::Layout best = r.best_layout;
  // A searched layout says what made it: not the start's name and description.
  best.name = "optimized-" + opt.metric;
  best.description = "lmc optimize --metric " + opt.metric + ": " + std::to_string(opt.starts) + " start(s) of " +
                     std::to_string(s.particles) + " particles × " + std::to_string(s.iterations) +
                     " iterations (seed " + std::to_string(multi.seeds.at(static_cast<size_t>(multi.best))) + ") on " +
                     poses.description + ", " + cost_name + " = " + std::to_string(r.best_cost);
  lmc::save_layout(best, opt.output);

  std::vector<std::string> slots;
  for (const auto& d : best.devices) slots.push_back(d.slot);
  if (opt.json) {
    print_search_json(opt, multi, best, slots, s.weights);
  } else {
    print_search_text(opt, multi, best, slots, s.weights, poses.description, cost_name);
  }
}

void setup_optimize(CLI::App& app) {
  auto opt = std::make_shared<OptimizeOptions>();
  app.add_option("--poses", opt->poses,
                 "\"mc\" (Monte Carlo set), a pose-set file from `lmc poses` (Monte Carlo or recorded) or a recipe "
                 "(.json) mixing recordings and the Monte Carlo set with weights");
  app.add_option("--frames", opt->frames, "Frames of the Monte Carlo set")->check(CLI::Range(1, 10'000'000));
  app.add_option("--seed", opt->seed, "Seed of the Monte Carlo set");
  app.add_option("--hand", opt->hand, "Monte Carlo set with the hand of this LMC recording's first row");
  app.add_option("--devices", opt->devices, "Number of devices when no --start layout is given")
      ->check(CLI::Range(1, 8));
  app.add_option("--particles", opt->particles, "Swarm size")->check(CLI::Range(1, 100000));
  app.add_option("--iterations", opt->iterations, "PSO iterations")->check(CLI::Range(0, 1000000));
  app.add_option("--w", opt->w, "Inertia weight");
  app.add_option("--c1", opt->c1, "Cognitive coefficient");
  app.add_option("--c2", opt->c2, "Social coefficient");
  app.add_option("--pso-seed", opt->pso_seed, "Seed of the swarm");
  app.add_option("--threads", opt->threads, "Worker threads (0 = all); the result does not depend on it")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--bounds", opt->bounds,
                 "Searched parameters and bounds, e.g. x=-400:400,z=-400:400,rx=-45:45,ry=-180:180 "
                 "(default with --metric study: the authors' box x,z ∈ [-1000,1000], rx ∈ [-90,90], ry ∈ [-180,180]; "
                 "with --metric robust: the table, x,z ∈ [-360,360])");
  app.add_option("--range-mm", opt->range_mm,
                 "Sensor range (mm); default: the --start layout's, else 600 as in the study")
      ->check(CLI::PositiveNumber);
  app.add_option("--radius-mm", opt->radius_mm, "Phalanx radius (mm)")->check(CLI::NonNegativeNumber);
  app.add_option("--models", opt->models,
                 "Sensor models from the catalogue (assets/sensors/sensors.json) for the searched controllers: one "
                 "id for all, or one per controller in order (lmc2,lmc2,lmc,lmc); each slot keeps its model");
  app.add_option("--start", opt->start, "Start from this layout (file or preset); its devices are searched");
  app.add_option("--lock", opt->locks, "Keep a device (SLOT) or some of its parameters (SLOT:x+rz) at the start value");
  app.add_option("-o,--output", opt->output, "Write the best layout here (JSON)")->required();
  app.add_option("--metric", opt->metric,
                 "study: the study's M alone (the reference); robust: M, then the tie-breakers of "
                 "core/metric/robust_metric.h (default)")
      ->check(CLI::IsMember({"study", "robust"}));
  app.add_option("--starts", opt->starts, "Independent swarms (seeds --pso-seed, +1, ...); the best wins")
      ->check(CLI::Range(1, 64));
  app.add_option("--w-redundancy", opt->weights.redundancy, "Robust metric: weight of the redundancy term (0 = off)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--w-participation", opt->weights.participation, "Robust metric: weight of the participation term")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--w-axis-cut", opt->weights.axis_cut, "Robust metric: weight of the axis-cut term")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--w-centring", opt->weights.centring, "Robust metric: weight of the centring term")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--w-footprint", opt->weights.footprint, "Robust metric: weight of the footprint-overlap term")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--w-inside-cut", opt->weights.inside_cut,
                 "Robust metric: weight of M counting only markers inside each controller's axis cut (what the "
                 "controllers can measure; 0 = reported, not searched on)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--json", opt->json, "Print the summary as JSON on stdout");
  app.add_flag("--no-progress", opt->no_progress, "No progress bar on stderr");
  app.add_flag("--exhaustive", opt->exhaustive,
               "Count every particle on every frame instead of stopping one whose cost cannot beat its own best "
               "(the same result, slower; to check that)");
  app.callback([opt] { run_optimize(*opt); });
}

const lmc::cli::CommandRegistration optimize_command{"optimize", "Search device placements with a particle swarm", 50,
                                                     setup_optimize};

}  // namespace
