// lmc bench: visibility throughput and search time on the default Monte Carlo pose set.
//
// Text and --json report the same figures. JSON keys:
//   "frames"            pose-set size (default 10000, Monte Carlo seed 1)
//   "threads"           threads used for the "all threads" figures
//   "kernel_build"      the visibility kernel's build that ran: "AVX-512", "AVX2" or "baseline"
//   "cases"             array of {"name", "layouts", "devices",
//                        "single_thread_evals_per_s", "all_threads_evals_per_s"}: (device, frame)
//                        visibility tests per second including the c_i reduction, for
//                        "paper-initial" (every device sees the whole hand: every test runs),
//                        "paper-optimized" and "random" (30 random 4-device layouts from the
//                        authors' search box)
//   "search"            {"particles", "iterations", "seconds", "evals_per_s", "best_cost"} for
//                        one PSO run on all threads (absent with --no-search)
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <iostream>
#include <random>

#include "app/lmc/command.h"
#include "core/io/pose_source.h"
#include "core/io/layout_json.h"
#include "core/optimise/pso.h"
#include "core/optimise/swarm_evaluator.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"

namespace {

struct BenchOptions {
  int frames = lmc::kDefaultMonteCarloFrames;
  int particles = 30;
  int iterations = 100;
  double min_seconds = 1.0;
  bool no_search = false;
  bool json = false;
};

struct CaseResult {
  std::string name;
  int layouts = 0;
  int devices = 0;
  double single = 0;
  double all = 0;
};

// (device, frame) evaluations per second of worst_finger_histograms over `views` in an arena of
// `threads`, repeated until at least `min_seconds` have passed.
double measure(const std::vector<lmc::DeviceView>& views, int layouts, int devices,
               const std::vector<lmc::PreparedFrame>& frames, const lmc::VisibilityLimits& limits, int threads,
               double min_seconds) {
  tbb::task_arena arena(threads);
  std::vector<std::int64_t> counts(static_cast<size_t>(layouts) * static_cast<size_t>(devices + 1));
  const auto t0 = std::chrono::steady_clock::now();
  long reps = 0;
  double elapsed = 0;
  do {
    arena.execute([&] { lmc::worst_finger_histograms(views, layouts, devices, frames, limits, counts); });
    ++reps;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  } while (elapsed < min_seconds);
  return static_cast<double>(reps) * static_cast<double>(views.size()) * static_cast<double>(frames.size()) / elapsed;
}

void setup_bench(CLI::App& app) {
  auto opt = std::make_shared<BenchOptions>();
  app.add_option("--frames", opt->frames, "Monte Carlo frames")->check(CLI::Range(1, 10'000'000));
  app.add_option("--particles", opt->particles, "Particles of the timed search")->check(CLI::Range(1, 100000));
  app.add_option("--iterations", opt->iterations, "Iterations of the timed search")->check(CLI::Range(0, 1000000));
  app.add_option("--min-seconds", opt->min_seconds, "Minimum time per throughput figure")->check(CLI::PositiveNumber);
  app.add_flag("--no-search", opt->no_search, "Skip the timed search");
  app.add_flag("--json", opt->json, "Print JSON (keys documented in app/lmc/commands/bench.cpp)");
  app.callback([opt] {
    const lmc::PoseSet poses = lmc::load_poses("mc", opt->frames, lmc::kDefaultMonteCarloSeed);
    const auto frames = lmc::prepare_frames(poses.frames);
    const int threads = tbb::info::default_concurrency();
    std::vector<CaseResult> results;
    auto run_case = [&](const std::string& name, const std::vector<lmc::Layout>& layouts) {
      std::vector<lmc::DeviceView> views;
      for (const auto& l : layouts) {
        for (const auto& d : l.devices) views.push_back(lmc::DeviceView::from_device(d));
      }
      const int devices = layouts.front().device_count();
      const auto limits = lmc::make_limits(lmc::VisibilityParams::from_sensor(layouts.front().sensor));
      CaseResult r{name, static_cast<int>(layouts.size()), devices, 0, 0};
      r.single = measure(views, r.layouts, devices, frames, limits, 1, opt->min_seconds);
      r.all = measure(views, r.layouts, devices, frames, limits, threads, opt->min_seconds);
      results.push_back(r);
      if (!opt->json) {
        std::printf("%-16s %2d layout(s) × %d devices: %12.0f evaluations/s on 1 thread, %12.0f on %d threads\n",
                    name.c_str(), r.layouts, devices, r.single, r.all, threads);
        std::fflush(stdout);
      }
    };
    // Which of the kernel's builds runs here (they give the same bits; the speed differs, and
    // LMC_KERNEL=avx2 etc. picks another to compare).
    const char* kernel = lmc::kernel_build_name(lmc::KernelBuild::kBest);
    if (const std::string problem = lmc::kernel_setting_problem(); !problem.empty()) {
      std::fprintf(stderr, "lmc bench: %s\n", problem.c_str());
    }
    if (!opt->json) std::printf("%d Monte Carlo frames (seed 1), visibility kernel: %s build\n", opt->frames, kernel);
    run_case("paper-initial", {lmc::load_layout_or_preset("paper-initial")});
    run_case("paper-optimized", {lmc::load_layout_or_preset("paper-optimized")});
    {
      std::mt19937_64 rng(12345);
      const lmc::SearchSpace space;
      std::vector<lmc::Layout> layouts;
      for (int i = 0; i < 30; ++i) {
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
      run_case("random", layouts);
    }
    nlohmann::json j;
    j["frames"] = opt->frames;
    j["threads"] = threads;
    j["kernel_build"] = kernel;
    j["cases"] = nlohmann::json::array();
    for (const auto& r : results) {
      j["cases"].push_back({{"name", r.name},
                            {"layouts", r.layouts},
                            {"devices", r.devices},
                            {"single_thread_evals_per_s", r.single},
                            {"all_threads_evals_per_s", r.all}});
    }
    if (!opt->no_search) {
      lmc::PsoSettings s;
      s.particles = opt->particles;
      s.iterations = opt->iterations;
      const lmc::PsoResult pr = lmc::run_pso(lmc::default_start_layout(4), lmc::SearchSpace{}, frames, s);
      const double rate = static_cast<double>(pr.device_frame_evaluations) / pr.seconds;
      j["search"] = {{"particles", s.particles},
                     {"iterations", s.iterations},
                     {"seconds", pr.seconds},
                     {"evals_per_s", rate},
                     {"best_cost", pr.best_cost}};
      if (!opt->json) {
        std::printf("search %d particles × %d iterations, 4 devices, %d frames, %d threads: %.2f s (%.0f evaluations/s), "
                    "best M %.6g\n",
                    s.particles, s.iterations, opt->frames, threads, pr.seconds, rate, pr.best_cost);
      }
    }
    if (opt->json) std::cout << j.dump(2) << "\n";
  });
}

const lmc::cli::CommandRegistration bench_command{
    "bench", "Measure visibility throughput and search time", 90, setup_bench};

}  // namespace
