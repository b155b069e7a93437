// lmc bench: visibility throughput, what the robust metric's terms cost, and search times on the
// default Monte Carlo pose set; with --processing DIR, what processing a session folder takes.
// Text and --json report the same figures; the JSON keys and their meaning are documented once,
// in docs/cli.md ("lmc bench --json"), and a key added here is added there.
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>

#include "app/lmc/command.h"
#include "app/lmc/commands/bench_processing.h"
#include "core/io/layout_json.h"
#include "core/io/pose_source.h"
#include "core/metric/layout_tally.h"
#include "core/optimise/pso.h"
#include "core/optimise/search_space.h"
#include "core/optimise/swarm_evaluator.h"
#include "core/stats/percentile.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"

namespace {

struct BenchOptions {
  int frames = lmc::kDefaultMonteCarloFrames;
  int particles = 30;
  int iterations = 100;
  double min_seconds = 1.0;
  bool no_search = false;
  std::vector<std::string> searches{"study-box", "study-table", "robust-table"};
  bool json = false;
  std::string processing;  // a session folder: time processing it instead
  int runs = 3;
};

// The timed searches. study-box is the study's search as the authors ran it; the table pair runs
// the robust search's default bounds with either metric, so that their ratio is the cost of the
// robust terms alone: a search on the table is slower with either metric, because there every
// controller sees the hand and its visibility test cannot exit early.
struct TimedSearch {
  const char* name;
  lmc::PlacementMetricKind metric;
  bool table;
};
constexpr TimedSearch kTimedSearches[] = {{"study-box", lmc::PlacementMetricKind::kStudy, false},
                                          {"study-table", lmc::PlacementMetricKind::kStudy, true},
                                          {"robust-table", lmc::PlacementMetricKind::kRobust, true}};

struct CaseResult {
  std::string name;
  int layouts = 0;
  int devices = 0;
  double single = 0;
  double all = 0;
};

// (device, frame) evaluations per second of worst_finger_histograms over `views` in an arena of
// `threads`, repeated until at least `min_seconds` have passed.
// Slot d of every layout sees through slot_limits[d] (a mixed rig when they differ).
double measure(const std::vector<lmc::DeviceView>& views, int layouts, int devices,
               const std::vector<lmc::PreparedFrame>& frames, std::span<const lmc::VisibilityLimits> slot_limits,
               int threads, double min_seconds) {
  const std::vector<lmc::FrameRun> runs = lmc::chunk_runs(frames.size());
  tbb::task_arena arena(threads);
  std::vector<std::int64_t> counts(static_cast<size_t>(layouts) * static_cast<size_t>(devices + 1));
  const auto t0 = std::chrono::steady_clock::now();
  long reps = 0;
  double elapsed = 0;
  do {
    arena.execute([&] { lmc::worst_finger_histograms(views, layouts, devices, frames, runs, slot_limits, counts); });
    ++reps;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  } while (elapsed < min_seconds);
  return static_cast<double>(reps) * static_cast<double>(views.size()) * static_cast<double>(frames.size()) / elapsed;
}

// What the robust metric's terms cost per evaluation, measured so that the machine's drift (runs
// of the same search differ widely, in phases of seconds) cancels: the study's
// histograms and the robust tallies of the same layouts on the same frames, one thread, in short
// adjacent pairs (the order swapped every pair), until `min_seconds` have passed and at least 15
// pairs ran; the median of the pairs' ratios, and the median time of each.
struct PairedTimes {
  double study_s = 0;
  double robust_s = 0;
  double ratio = 0;
  int pairs = 0;
};
PairedTimes measure_terms_cost(const std::vector<lmc::DeviceView>& views, int layouts, int devices,
                               std::span<const lmc::PreparedFrame> frames, const lmc::VisibilityLimits& limits,
                               double min_seconds) {
  tbb::task_arena arena(1);
  std::vector<std::int64_t> counts(static_cast<size_t>(layouts) * static_cast<size_t>(devices + 1));
  std::vector<lmc::LayoutTally> tallies(static_cast<size_t>(layouts), lmc::LayoutTally(devices));
  auto seconds_of = [&](bool robust) {
    const auto t0 = std::chrono::steady_clock::now();
    arena.execute([&] {
      if (robust) {
        lmc::layout_tallies(views, layouts, devices, frames, limits, lmc::kAxisCutMm, tallies);
      } else {
        lmc::worst_finger_histograms(views, layouts, devices, frames, limits, counts);
      }
    });
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  std::vector<double> study, robust, ratio;
  double total = 0;
  while (ratio.size() < 15 || total < min_seconds) {
    const bool robust_first = ratio.size() % 2 == 1;
    const double first = seconds_of(robust_first), second = seconds_of(!robust_first);
    study.push_back(robust_first ? second : first);
    robust.push_back(robust_first ? first : second);
    ratio.push_back(robust.back() / study.back());
    total += first + second;
  }
  const auto median = [](const std::vector<double>& v) { return lmc::percentile(v, 50.0); };
  return {median(study), median(robust), median(ratio), static_cast<int>(ratio.size())};
}

// Mixed rigs against uniform rigs of their models, in adjacent rounds so that the machine's drift
// cancels: each round times LMC × 4, LMC2 × 4 and the two mixed rigs (one thread, the order rotated
// every round) until `min_seconds` have passed and at least 15 rounds ran.
struct MixedRigTimes {
  double lmc_s = 0, lmc2_s = 0, mixed_s = 0, swapped_s = 0, ratio = 0;
  int rounds = 0;
};
MixedRigTimes measure_mixed_rig(const std::vector<lmc::DeviceView>& views, int layouts, int devices,
                                std::span<const lmc::PreparedFrame> frames,
                                const std::array<std::vector<lmc::VisibilityLimits>, 4>& rigs, double min_seconds) {
  tbb::task_arena arena(1);
  const std::vector<lmc::FrameRun> runs = lmc::chunk_runs(frames.size());
  std::vector<std::int64_t> counts(static_cast<size_t>(layouts) * static_cast<size_t>(devices + 1));
  auto seconds_of = [&](size_t rig) {
    const auto t0 = std::chrono::steady_clock::now();
    arena.execute([&] { lmc::worst_finger_histograms(views, layouts, devices, frames, runs, rigs[rig], counts); });
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  std::array<std::vector<double>, 4> times;
  std::vector<double> ratio;
  double total = 0;
  while (ratio.size() < 15 || total < min_seconds) {
    std::array<double, 4> t{};
    for (size_t k = 0; k < 4; ++k) {
      const size_t rig = (k + ratio.size()) % 4;
      t[rig] = seconds_of(rig);
      total += t[rig];
    }
    for (size_t rig = 0; rig < 4; ++rig) times[rig].push_back(t[rig]);
    ratio.push_back((t[2] + t[3]) / (t[0] + t[1]));
  }
  const auto median = [](const std::vector<double>& v) { return lmc::percentile(v, 50.0); };
  return {median(times[0]), median(times[1]), median(times[2]),
          median(times[3]), median(ratio),    static_cast<int>(ratio.size())};
}

// `count` layouts of 4 devices drawn uniformly from `space` (fixed seed).
std::vector<lmc::Layout> random_layouts(const lmc::SearchSpace& space, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<lmc::Layout> layouts;
  for (int i = 0; i < count; ++i) {
    lmc::Layout l = lmc::default_start_layout(4);
    for (auto& d : l.devices) {
      for (int k = 0; k < lmc::kNumPoseParams; ++k) {
        if (!space.free[static_cast<size_t>(k)]) continue;
        const auto& b = space.bounds[static_cast<size_t>(k)];
        d.pose.set(k, b.min + (b.max - b.min) * static_cast<double>(rng() >> 11) * 0x1.0p-53);
      }
    }
    layouts.push_back(l);
  }
  return layouts;
}

std::vector<lmc::DeviceView> views_of(const std::vector<lmc::Layout>& layouts) {
  std::vector<lmc::DeviceView> views;
  for (const auto& l : layouts) {
    for (const auto& d : l.devices) views.push_back(lmc::DeviceView::from_device(d));
  }
  return views;
}

// Throughput of one case (layouts of one rig) on one thread and on all; printed unless --json.
CaseResult run_case(const BenchOptions& opt, const std::string& name, const std::vector<lmc::Layout>& layouts,
                    const std::vector<lmc::PreparedFrame>& frames, int threads) {
  const std::vector<lmc::DeviceView> views = views_of(layouts);
  const int devices = layouts.front().device_count();
  // Each slot through its own sensor model (the same in every layout of a case).
  const std::vector<lmc::VisibilityLimits> limits = lmc::device_limits(layouts.front());
  CaseResult r{name, static_cast<int>(layouts.size()), devices, 0, 0};
  r.single = measure(views, r.layouts, devices, frames, limits, 1, opt.min_seconds);
  r.all = measure(views, r.layouts, devices, frames, limits, threads, opt.min_seconds);
  if (!opt.json) {
    std::printf("%-16s %2d layout(s) × %d devices: %12.0f evaluations/s on 1 thread, %12.0f on %d threads\n",
                name.c_str(), r.layouts, devices, r.single, r.all, threads);
    std::fflush(stdout);
  }
  return r;
}

// The paper's two layouts, 30 random ones, and the same random ones as rigs of other models: a
// mixed rig should cost what its devices cost in rigs of their own model.
std::vector<CaseResult> run_cases(const BenchOptions& opt, const std::vector<lmc::PreparedFrame>& frames, int threads) {
  std::vector<CaseResult> results;
  results.push_back(run_case(opt, "paper-initial", {lmc::load_layout_or_preset("paper-initial")}, frames, threads));
  results.push_back(run_case(opt, "paper-optimized", {lmc::load_layout_or_preset("paper-optimized")}, frames, threads));
  results.push_back(run_case(opt, "random", random_layouts(lmc::SearchSpace{}, 30, 12345), frames, threads));
  for (const char* models : {"lmc", "lmc2", "lmc2,lmc2,lmc,lmc"}) {
    std::vector<lmc::Layout> layouts = random_layouts(lmc::SearchSpace{}, 30, 12345);
    for (auto& l : layouts) lmc::set_models_from_list(l, models, lmc::sensor_catalogue());
    const std::string name = std::string(models).find(',') == std::string::npos ? "random-" + std::string(models)
                                                                                : std::string("random-mixed");
    results.push_back(run_case(opt, name, layouts, frames, threads));
  }
  return results;
}

nlohmann::json mixed_rig_figure(const BenchOptions& opt, const std::vector<lmc::PreparedFrame>& frames) {
  std::array<std::vector<lmc::VisibilityLimits>, 4> rigs;
  const char* models[] = {"lmc", "lmc2", "lmc2,lmc2,lmc,lmc", "lmc,lmc,lmc2,lmc2"};
  for (size_t k = 0; k < 4; ++k) {
    lmc::Layout rig = lmc::default_start_layout(4);
    lmc::set_models_from_list(rig, models[k], lmc::sensor_catalogue());
    rigs[k] = lmc::device_limits(rig);
  }
  const std::span<const lmc::PreparedFrame> some(frames.data(), std::min<size_t>(frames.size(), 2000));
  const MixedRigTimes m = measure_mixed_rig(views_of(random_layouts(lmc::SearchSpace{}, 30, 12345)), 30, 4, some, rigs,
                                            2.0 * opt.min_seconds);
  if (!opt.json) {
    std::printf(
        "mixed rigs: %.3f × the uniform rigs of their models (30 random layouts × %zu frames, 1 thread: LMC × 4 "
        "%.1f ms, LMC2 × 4 %.1f ms, LMC2 LMC2 LMC LMC %.1f ms, LMC LMC LMC2 LMC2 %.1f ms; medians of %d "
        "adjacent rounds)\n",
        m.ratio, some.size(), 1e3 * m.lmc_s, 1e3 * m.lmc2_s, 1e3 * m.mixed_s, 1e3 * m.swapped_s, m.rounds);
    std::fflush(stdout);
  }
  return {{"frames", some.size()},    {"rounds", m.rounds},         {"lmc_seconds", m.lmc_s},
          {"lmc2_seconds", m.lmc2_s}, {"mixed_seconds", m.mixed_s}, {"mixed_swapped_seconds", m.swapped_s},
          {"ratio", m.ratio}};
}

nlohmann::json robust_terms_figure(const BenchOptions& opt, const std::vector<lmc::PreparedFrame>& frames) {
  const lmc::SearchSpace table = lmc::table_search_space();
  const std::vector<lmc::Layout> layouts = random_layouts(table, 30, 54321);
  const auto limits = lmc::make_limits(lmc::VisibilityParams::from_sensor(lmc::common_sensor(layouts.front())));
  // The first 2,000 frames: pairs of ~0.1 s fit between the machine's slow phases.
  const std::span<const lmc::PreparedFrame> some(frames.data(), std::min<size_t>(frames.size(), 2000));
  const PairedTimes p = measure_terms_cost(views_of(layouts), 30, 4, some, limits, 2.0 * opt.min_seconds);
  if (!opt.json) {
    std::printf(
        "robust terms per evaluation: %+.1f %% (30 random layouts on the table × %zu frames, 1 thread: "
        "study %.1f ms, robust %.1f ms; medians of %d adjacent pairs)\n",
        100.0 * (p.ratio - 1.0), some.size(), 1e3 * p.study_s, 1e3 * p.robust_s, p.pairs);
    std::fflush(stdout);
  }
  return {{"layouts", 30},        {"frames", some.size()},      {"bounds", lmc::format_search_bounds(table)},
          {"pairs", p.pairs},     {"study_seconds", p.study_s}, {"robust_seconds", p.robust_s},
          {"cost", p.ratio - 1.0}};
}

// The timed searches --searches names, into j["searches"] (and j["search"], j["robust_terms_cost"]).
void run_timed_searches(const BenchOptions& opt, const std::vector<lmc::PreparedFrame>& frames, int threads,
                        nlohmann::json& j) {
  j["searches"] = nlohmann::json::array();
  if (!opt.json) {
    std::printf("searches of %d particles × %d iterations, 4 devices, %d frames, %d threads:\n", opt.particles,
                opt.iterations, opt.frames, threads);
  }
  std::map<std::string, double> seconds;
  for (const TimedSearch& t : kTimedSearches) {
    if (std::find(opt.searches.begin(), opt.searches.end(), t.name) == opt.searches.end()) continue;
    lmc::PsoSettings s;
    s.particles = opt.particles;
    s.iterations = opt.iterations;
    s.metric = t.metric;
    const lmc::SearchSpace space = t.table ? lmc::table_search_space() : lmc::SearchSpace{};
    const lmc::PsoResult pr = lmc::run_pso(lmc::default_start_layout(4), space, frames, s);
    const double rate = static_cast<double>(pr.device_frame_evaluations) / pr.seconds;
    const std::string metric = t.metric == lmc::PlacementMetricKind::kRobust ? "robust" : "study";
    const std::string bounds = lmc::format_search_bounds(space);
    seconds[t.name] = pr.seconds;
    j["searches"].push_back({{"name", t.name},
                             {"metric", metric},
                             {"bounds", bounds},
                             {"particles", s.particles},
                             {"iterations", s.iterations},
                             {"seconds", pr.seconds},
                             {"evals_per_s", rate},
                             {"best_cost", pr.best_cost},
                             {"layouts_stopped_early", pr.layouts_stopped_early}});
    if (!t.table) {
      j["search"] = {{"particles", s.particles},
                     {"iterations", s.iterations},
                     {"seconds", pr.seconds},
                     {"evals_per_s", rate},
                     {"best_cost", pr.best_cost}};
    }
    if (!opt.json) {
      std::printf("  %-12s (%s metric, %s): %.2f s (%.0f evaluations/s), best %s %.6g\n", t.name, metric.c_str(),
                  bounds.c_str(), pr.seconds, rate, t.metric == lmc::PlacementMetricKind::kRobust ? "R" : "M",
                  pr.best_cost);
      std::fflush(stdout);
    }
  }
  if (seconds.contains("study-table") && seconds.contains("robust-table")) {
    const double cost = seconds["robust-table"] / seconds["study-table"] - 1.0;
    j["robust_terms_cost"] = cost;
    if (!opt.json) {
      std::printf(
          "  the robust terms cost %+.1f %% of a search on the same bounds (robust-table against "
          "study-table, one run each: the machine's drift between runs is in it; the figure per "
          "evaluation above is not)\n",
          100.0 * cost);
    }
  }
}

void run_bench(const BenchOptions& opt) {
  if (!opt.processing.empty()) {
    lmc::cli::run_processing_bench(opt.processing, opt.runs, opt.json);
    return;
  }
  const lmc::PoseSet poses = lmc::load_poses("mc", opt.frames, lmc::kDefaultMonteCarloSeed);
  const auto frames = lmc::prepare_frames(poses.frames);
  const int threads = tbb::info::default_concurrency();
  // Which of the kernel's builds runs here (they give the same bits; the speed differs, and
  // LMC_KERNEL=avx2 etc. picks another to compare).
  const char* kernel = lmc::kernel_build_name(lmc::KernelBuild::kBest);
  if (const std::string problem = lmc::kernel_setting_problem(); !problem.empty()) {
    std::fprintf(stderr, "lmc bench: %s\n", problem.c_str());
  }
  if (!opt.json) std::printf("%d Monte Carlo frames (seed 1), visibility kernel: %s build\n", opt.frames, kernel);
  const std::vector<CaseResult> results = run_cases(opt, frames, threads);
  const nlohmann::json mixed = mixed_rig_figure(opt, frames);
  const nlohmann::json terms = robust_terms_figure(opt, frames);
  nlohmann::json j;
  j["frames"] = opt.frames;
  j["threads"] = threads;
  j["kernel_build"] = kernel;
  j["terms_per_evaluation"] = terms;
  j["mixed_rig"] = mixed;
  j["cases"] = nlohmann::json::array();
  for (const auto& r : results) {
    j["cases"].push_back({{"name", r.name},
                          {"layouts", r.layouts},
                          {"devices", r.devices},
                          {"single_thread_evals_per_s", r.single},
                          {"all_threads_evals_per_s", r.all}});
  }
  if (!opt.no_search) run_timed_searches(opt, frames, threads, j);
  if (opt.json) std::cout << j.dump(2) << "\n";
}

void setup_bench(CLI::App& app) {
  auto opt = std::make_shared<BenchOptions>();
  app.add_option("--frames", opt->frames, "Monte Carlo frames")->check(CLI::Range(1, 10'000'000));
  app.add_option("--particles", opt->particles, "Particles of each timed search")->check(CLI::Range(1, 100000));
  app.add_option("--iterations", opt->iterations, "Iterations of each timed search")->check(CLI::Range(0, 1000000));
  app.add_option("--min-seconds", opt->min_seconds, "Minimum time per throughput figure")->check(CLI::PositiveNumber);
  app.add_flag("--no-search", opt->no_search, "Skip the timed searches");
  app.add_option("--searches", opt->searches,
                 "Timed searches, comma-separated: study-box (the study's metric in the authors' box), study-table and "
                 "robust-table (either metric on the table, the robust search's bounds); default all three")
      ->delimiter(',')
      ->check(CLI::IsMember({"study-box", "study-table", "robust-table"}));
  app.add_flag("--json", opt->json, "Print JSON (keys documented in app/lmc/commands/bench.cpp)");
  app.add_option("--processing", opt->processing,
                 "Instead of the placement figures, time processing this session folder as lmc process does (default "
                 "method, then both methods), outputs to a scratch folder");
  app.add_option("--runs", opt->runs, "Runs of each processing figure (the median is reported)")
      ->check(CLI::Range(1, 100));
  app.callback([opt] { run_bench(*opt); });
}

const lmc::cli::CommandRegistration bench_command{
    "bench", "Measure visibility throughput, what the robust terms cost, and search times", 90, setup_bench};

}  // namespace
