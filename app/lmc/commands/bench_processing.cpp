#include "app/lmc/commands/bench_processing.h"

#include <tbb/info.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "core/common/error.h"
#include "core/platform/process.h"
#include "core/results/batch_outputs.h"
#include "core/session/session_trials.h"
#include "core/stats/percentile.h"
#include "devices/host_memory.h"
#include "devices/soak/process_stats.h"

namespace lmc::cli {
namespace {

double median(const std::vector<double>& v) {
  return percentile(v, 50.0);  // the rule bench.cpp's search figures use
}

struct Timing {
  std::vector<double> wall, cpu;
  int trials = 0;
};

Timing time_runs(const std::vector<TrialSources>& jobs, bool compare_methods, int runs,
                 const std::filesystem::path& scratch) {
  Timing t;
  for (int k = 0; k < runs; ++k) {
    std::filesystem::remove_all(scratch);
    BatchOptions options;
    options.compare_methods = compare_methods;
    const double cpu0 = devices::process_cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    const auto outcomes = process_and_write_batch(jobs, options, scratch);
    t.wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    t.cpu.push_back(devices::process_cpu_seconds() - cpu0);
    t.trials = 0;
    for (const auto& o : outcomes) {
      if (!o.ok) throw Error(o.trial + ": " + o.error);
      ++t.trials;
    }
  }
  return t;
}

nlohmann::json timing_json(const Timing& t) {
  return {{"wall_seconds", t.wall},
          {"cpu_seconds", t.cpu},
          {"median_wall_s", median(t.wall)},
          {"median_cpu_s", median(t.cpu)}};
}

}  // namespace

void run_processing_bench(const std::string& input, int runs, bool json) {
  devices::keep_freed_memory_for_reuse();
  std::vector<std::string> notes;
  const auto jobs = trial_sources_for_input(input, std::nullopt, &notes);
  if (jobs.empty()) throw Error(ErrorLocation(input), "no trials to process");
  const auto scratch = std::filesystem::temp_directory_path() /
                       ("lmc-bench-processing-" + std::to_string(platform::current_process_id()));
  struct RemoveScratch {
    std::filesystem::path dir;
    ~RemoveScratch() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  } remove_scratch{scratch};
  const Timing single = time_runs(jobs, false, runs, scratch);
  const Timing both = time_runs(jobs, true, runs, scratch);
  const int threads = tbb::info::default_concurrency();
  if (json) {
    const nlohmann::json j{{"processing",
                            {{"input", input},
                             {"trials", single.trials},
                             {"runs", runs},
                             {"threads", threads},
                             {"default", timing_json(single)},
                             {"both", timing_json(both)}}}};
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("processing %d trial(s) of %s on %d thread(s), %d run(s) each, outputs written and synced:\n",
              single.trials, input.c_str(), threads, runs);
  std::printf("  default method: median %.2f s wall, %.2f s CPU\n", median(single.wall), median(single.cpu));
  std::printf("  both methods:   median %.2f s wall, %.2f s CPU\n", median(both.wall), median(both.cpu));
}

}  // namespace lmc::cli
