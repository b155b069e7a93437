// Google Benchmark for the Review tab and `lmc figures`:
//   BM_ReviewReopenCached80    opening an 80-trial folder whose trials are in the processing cache
//                              (goal ≤ 1 s): discovery, cache look-ups and the table rows;
//   BM_ReviewExport80          everything `lmc figures` writes for 80 processed trials (goal, with
//                              processing from the cache: ≤ 10 s);
//   BM_ReviewFramePlots        one frame's plot work while scrubbing: 6 plots × 4 series of a 10 s
//                              trial decimated to 600 columns (goal: well inside 16 ms).
// The 80 trials are copies of the study's real trial (the study's data folder, 4 controllers, with
// its Vicon file) under the protocol's 80 names; without it the first two report an error and skip.
// Run: build/release/tests/lmc_benchmarks --benchmark_filter=Review
#include <benchmark/benchmark.h>

#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stop_token>
#include <vector>

#include "core/review/review_export.h"
#include "tests/support/build_paths.h"
#include "ui/model/plot/min_max_decimation.h"
#include "ui/model/review/review_batch_job.h"

namespace {

namespace fs = std::filesystem;

fs::path reference_validation_dir() {
  if (const char* env = std::getenv("LMC_REFERENCE_DATA_DIR"); env != nullptr && *env != '\0')
    return fs::path(env) / "validation";
  return lmc::test::default_reference_dir() / "validation";
}

// 80 trials in one folder and their cache entries, made once per process.
struct EightyTrials {
  fs::path folder, cache, out;
  bool ok = false;
};

const EightyTrials& eighty_trials() {
  static const EightyTrials made = [] {
    EightyTrials e;
    const fs::path src = reference_validation_dir();
    if (!fs::exists(src / "Interp_LMC_Naiv_Static101.txt")) return e;
    const fs::path root = fs::temp_directory_path() / ("lmc_bench_review_" + std::to_string(::getpid()));
    fs::remove_all(root);
    e.folder = root / "S01";
    e.cache = root / "cache";
    e.out = root / "out";
    fs::create_directories(e.folder);
    for (const char* layout : {"Naiv", "Opti"}) {
      for (const char* motion : {"Static", "Index", "Thumb", "Wrist"}) {
        for (int pose = 1; pose <= 2; ++pose) {
          for (int rep = 1; rep <= 5; ++rep) {
            const std::string trial =
                std::string(layout) + "_" + motion + std::to_string(pose) + "0" + std::to_string(rep);
            fs::copy_file(src / "Interp_LMC_Naiv_Static101.txt", e.folder / ("Interp_LMC_" + trial + ".txt"));
            fs::copy_file(src / "Naiv_Static101.trc", e.folder / (trial + ".trc"));
          }
        }
      }
    }
    lmc::ui::ReviewBatchInput in{{e.folder}, {}, e.cache, {}};
    std::stop_source never;
    const auto primed = lmc::ui::run_review_batch(in, never.get_token(), {});
    e.ok = primed.trials.size() == 80 && primed.processed_now == 80;
    return e;
  }();
  return made;
}

// The 80 trials, or null after telling the benchmark why it cannot run.
const EightyTrials* eighty_trials_or_skip(benchmark::State& state) {
  const EightyTrials& e = eighty_trials();
  if (e.ok) return &e;
  state.SkipWithError("needs the study's data folder (set LMC_REFERENCE_DATA_DIR)");
  return nullptr;
}

void BM_ReviewReopenCached80(benchmark::State& state) {
  const EightyTrials* e = eighty_trials_or_skip(state);
  if (e == nullptr) return;
  const lmc::ui::ReviewBatchInput in{{e->folder}, {}, e->cache, {}};
  std::stop_source never;
  for (auto _ : state) {
    const auto batch = lmc::ui::run_review_batch(in, never.get_token(), {});
    if (batch.from_cache != 80) state.SkipWithError("not every trial came from the cache");
    benchmark::DoNotOptimize(batch.trials.data());
  }
}
BENCHMARK(BM_ReviewReopenCached80)->Unit(benchmark::kMillisecond);

void BM_ReviewExport80(benchmark::State& state) {
  const EightyTrials* e = eighty_trials_or_skip(state);
  if (e == nullptr) return;
  const lmc::ui::ReviewBatchInput in{{e->folder}, {}, e->cache, {}};
  std::stop_source never;
  const auto batch = lmc::ui::run_review_batch(in, never.get_token(), {});
  lmc::ReviewExportInput exports;
  for (const auto& t : batch.trials) exports.trials.push_back(lmc::agreement_trial("S01", t.outcome.summary));
  exports.method = "default";
  for (auto _ : state) {
    const auto files = lmc::write_review_exports(e->out, exports);
    benchmark::DoNotOptimize(files.data());
  }
}
BENCHMARK(BM_ReviewExport80)->Unit(benchmark::kMillisecond);

void BM_ReviewFramePlots(benchmark::State& state) {
  const size_t n = 1000;  // a 10 s trial at 100 Hz
  std::vector<double> x(n);
  std::vector<std::vector<double>> ys(24, std::vector<double>(n));
  for (size_t i = 0; i < n; ++i) {
    x[i] = static_cast<double>(i) * 0.01;
    for (size_t s = 0; s < ys.size(); ++s)
      ys[s][i] = (i + s) % 53 == 0 ? std::nan("") : std::sin(0.02 * static_cast<double>(i + 7 * s)) * 40;
  }
  for (auto _ : state) {
    for (const auto& y : ys) {
      auto cols = lmc::ui::decimate_min_max(x, y, 2.0, 7.0, 600);  // zoomed to 5 s
      benchmark::DoNotOptimize(cols.data());
    }
  }
}
BENCHMARK(BM_ReviewFramePlots)->Unit(benchmark::kMicrosecond);

}  // namespace
