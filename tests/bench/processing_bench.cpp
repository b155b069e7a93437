// Processing speed: one 10-second, four-device trial through each stage and the
// whole pipeline. The study's Python Kalman step cost ≈0.57 ms per frame per coordinate (≈50 s per
// trial); the end-to-end figure for a full simulated subject is measured with `lmc process` (it
// prints its time). Run: build/<release>/tests/lmc_benchmarks --benchmark_filter=Processing
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/io/layout_json.h"
#include "core/processing/fusion_smoother.h"
#include "core/processing/kalman_reference.h"
#include "core/processing/realign.h"
#include "core/processing/resample.h"
#include "core/processing/trial_pipeline.h"
#include "core/processing/visibility_labels.h"

namespace {

using namespace lmc;

// A flexing hand seen by four devices at 22–31 Hz for `seconds` (device frames of paper-initial).
LmcRecording synthetic_trial(const Layout& layout, double seconds) {
  LmcRecording rec;
  for (int d = 0; d < 4; ++d) {
    const auto& dev = layout.devices[static_cast<size_t>(d)];
    const Eigen::Matrix3d rt = dev.pose.rotation().transpose();
    const Eigen::Vector3d shift = dev.pose.translation() + dev.offset_mm;
    const double period = 1.0 / (22.0 + 3.0 * d);
    for (double t = 0.004 * d; t < seconds; t += period) {
      HandFrame f;
      f.device_id = d + 1;
      f.timestamp_us = 1'000'000 + static_cast<std::int64_t>(t * 1e6);
      f.hand_present = true;
      const double flex = 0.5 * (1 - std::cos(2 * M_PI * t / 3.0));
      for (int i = 0; i < kNumHandPoints; ++i) {
        const double k = i;
        const Vec3 w(-40 + 4 * k, 200 - flex * 2 * k, 60 - 6 * k + flex * k);
        f.point(i) = rt * (w - shift);
      }
      rec.rows.push_back(f);
    }
  }
  return rec;
}

const Layout& initial_layout() {
  static const Layout l = load_layout_or_preset("paper-initial");
  return l;
}

void BM_ProcessingResample(benchmark::State& state) {
  const LmcRecording rec = synthetic_trial(initial_layout(), 10.0);
  for (auto _ : state) benchmark::DoNotOptimize(resample_recording(rec));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ProcessingResample)->Unit(benchmark::kMillisecond);

void BM_ProcessingVisibilityLabels(benchmark::State& state) {
  const GridTrial g = resample_recording(synthetic_trial(initial_layout(), 10.0));
  for (auto _ : state) {
    for (const auto& d : g.devices) benchmark::DoNotOptimize(visibility_labels(d.track));
  }
}
BENCHMARK(BM_ProcessingVisibilityLabels)->Unit(benchmark::kMillisecond);

void BM_ProcessingFuseReference(benchmark::State& state) {
  GridTrial g = resample_recording(synthetic_trial(initial_layout(), 10.0));
  realign_to_world(g, initial_layout());
  std::vector<const HandTrack*> t;
  for (const auto& d : g.devices) t.push_back(&d.track);
  for (auto _ : state) benchmark::DoNotOptimize(fuse_reference(t));
  // Per frame per coordinate, to set against the study's ≈0.57 ms.
  state.counters["ns_per_frame_coord"] =
      benchmark::Counter(static_cast<double>(g.frame_count) * 90.0 * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ProcessingFuseReference)->Unit(benchmark::kMillisecond);

void BM_ProcessingFuseDefault(benchmark::State& state) {
  GridTrial g = resample_recording(synthetic_trial(initial_layout(), 10.0));
  realign_to_world(g, initial_layout());
  std::vector<const HandTrack*> t;
  for (const auto& d : g.devices) t.push_back(&d.track);
  for (auto _ : state) benchmark::DoNotOptimize(fuse_default(t, {}));
}
BENCHMARK(BM_ProcessingFuseDefault)->Unit(benchmark::kMillisecond);

void BM_ProcessingWholeTrial(benchmark::State& state) {
  const LmcRecording rec = synthetic_trial(initial_layout(), 10.0);
  ProcessOptions o;
  o.method = state.range(0) == 0 ? FusionMethod::kReference : FusionMethod::kDefault;
  for (auto _ : state) benchmark::DoNotOptimize(process_trial("Naiv_Index101", rec, initial_layout(), nullptr, o));
  state.SetLabel(state.range(0) == 0 ? "reference" : "default");
}
BENCHMARK(BM_ProcessingWholeTrial)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
