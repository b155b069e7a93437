// Google Benchmark for the plot widget's decimation (one million samples in under 2 ms
// per frame). Run: build/release/tests/lmc_benchmarks --benchmark_filter=Plot
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "ui/model/plot/min_max_decimation.h"

namespace {

void BM_PlotDecimateMillionSamples(benchmark::State& state) {
  const size_t n = 1'000'000;
  std::vector<double> x(n), y(n);
  for (size_t i = 0; i < n; ++i) {
    x[i] = static_cast<double>(i) * 0.01;  // 100 Hz: 2.8 hours of one series
    y[i] = (i % 997 == 0) ? std::nan("") : std::sin(static_cast<double>(i) * 0.001) * 40.0;
  }
  for (auto _ : state) {
    auto cols = lmc::ui::decimate_min_max(x, y, 0.0, 10000.0, 1200);
    benchmark::DoNotOptimize(cols.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
}
BENCHMARK(BM_PlotDecimateMillionSamples)->Unit(benchmark::kMillisecond);

}  // namespace
