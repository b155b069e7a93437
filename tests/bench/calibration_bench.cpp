// Calibrating four controllers from a 10 s still-hand trial (goal: < 0.5 s): the
// robust fit against Vicon and the consensus fit without it, on a synthetic trial with known
// errors (tests/support/synthetic_calibration.h). Input preparation (resampling, ray-traced
// labels) is the processing chain's and is measured with it.
#include <benchmark/benchmark.h>

#include "core/calibration/calibrate.h"
#include "tests/support/synthetic_calibration.h"

namespace calibration_bench {

const lmc::test::synthetic_calibration::Trial& trial(bool vicon) {
  namespace syn = lmc::test::synthetic_calibration;
  static const auto make = [](bool v) {
    const lmc::Layout layout = syn::square_layout();
    const auto truth = syn::perturbed(layout, {{40, -10, 25}, {-60, 30, 10}, {5, 5, -70}, {20, 0, 0}}, {8, -6, 10, 3});
    return syn::make_trial(truth, 1000, 1.0, 9, v);
  };
  static const auto with = make(true);
  static const auto without = make(false);
  return vicon ? with : without;
}

void BM_CalibrationWithVicon(benchmark::State& state) {
  const auto layout = lmc::test::synthetic_calibration::square_layout();
  const auto& t = trial(true);
  for (auto _ : state) benchmark::DoNotOptimize(lmc::calibrate(t.input, layout));
}
BENCHMARK(BM_CalibrationWithVicon)->Unit(benchmark::kMillisecond);

void BM_CalibrationWithoutVicon(benchmark::State& state) {
  const auto layout = lmc::test::synthetic_calibration::square_layout();
  const auto& t = trial(false);
  for (auto _ : state) benchmark::DoNotOptimize(lmc::calibrate(t.input, layout));
}
BENCHMARK(BM_CalibrationWithoutVicon)->Unit(benchmark::kMillisecond);

}  // namespace calibration_bench
