// Writing numbers as the study's text files hold them: the shortest form of a double (our
// write_shortest against std::to_chars, which it matches byte for byte) and four-decimal fixed
// point. The fused file of a subject is millions of such numbers (docs/results/processing.md).
// Run: build/<release>/tests/lmc_benchmarks --benchmark_filter=NumberText
#include <benchmark/benchmark.h>

#include <charconv>
#include <random>
#include <string>
#include <vector>

#include "core/common/number_format.h"
#include "core/common/shortest_double.h"

namespace {

// Millimetre coordinates as a fused file holds them: 17 significant digits, both signs.
std::vector<double> coordinates() {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> mm(-400.0, 400.0);
  std::vector<double> v(4096);
  for (double& x : v) x = mm(rng);
  return v;
}

void BM_NumberTextShortestStd(benchmark::State& state) {
  const auto values = coordinates();
  char buf[64];
  for (auto _ : state) {
    for (const double v : values) benchmark::DoNotOptimize(std::to_chars(buf, buf + sizeof buf, v).ptr);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values.size()));
}
BENCHMARK(BM_NumberTextShortestStd);

void BM_NumberTextShortestOurs(benchmark::State& state) {
  const auto values = coordinates();
  char buf[lmc::kShortestDoubleMaxChars];
  for (auto _ : state) {
    for (const double v : values) benchmark::DoNotOptimize(lmc::write_shortest(buf, v));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values.size()));
}
BENCHMARK(BM_NumberTextShortestOurs);

void BM_NumberTextFixedFourDecimals(benchmark::State& state) {
  const auto values = coordinates();
  std::string out;
  for (auto _ : state) {
    out.clear();
    for (const double v : values) lmc::append_fixed(out, v, 4);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values.size()));
}
BENCHMARK(BM_NumberTextFixedFourDecimals);

}  // namespace
