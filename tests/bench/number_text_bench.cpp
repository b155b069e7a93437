// Numbers as the study's text files hold them. Writing: the shortest form of a double (our
// write_shortest against std::to_chars, which it matches byte for byte) and four-decimal fixed
// point. Reading: our plain-decimal reader against std::from_chars (the same doubles). A subject's
// recordings, Vicon files and fused outputs are millions of such numbers
// (docs/results/processing.md).
// Run: build/<release>/tests/lmc_benchmarks --benchmark_filter=NumberText
#include <benchmark/benchmark.h>

#include <charconv>
#include <random>
#include <string>
#include <vector>

#include "core/common/number_format.h"
#include "core/common/plain_decimal.h"
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

// The coordinates as text, each followed by a tab as in a TRC row.
std::string coordinate_text() {
  std::string text;
  char buf[64];
  for (const double v : coordinates()) {
    text.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
    text += '\t';
  }
  return text;
}

// Reads every number of the text with `read` (first, last, value) → where the number ends.
template <typename Read>
void read_every_number(benchmark::State& state, Read read) {
  const std::string text = coordinate_text();
  for (auto _ : state) {
    const char* at = text.data();
    const char* const end = text.data() + text.size();
    while (at < end) {
      double v = 0.0;
      at = read(at, end, v) + 1;  // past the tab
      benchmark::DoNotOptimize(v);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(coordinates().size()));
}

void BM_NumberTextReadStd(benchmark::State& state) {
  read_every_number(state, [](const char* at, const char* end, double& v) { return std::from_chars(at, end, v).ptr; });
}
BENCHMARK(BM_NumberTextReadStd);

void BM_NumberTextReadOurs(benchmark::State& state) {
  read_every_number(state, [](const char* at, const char* end, double& v) {
    // As the recording and TRC readers call it: the text's end is the buffer's, so it may look
    // ahead (16 digits at a time with AVX2).
    const char* stop = lmc::read_plain_decimal(at, end, end, v);
    return stop != nullptr ? stop : std::from_chars(at, end, v).ptr;
  });
}
BENCHMARK(BM_NumberTextReadOurs);

}  // namespace
