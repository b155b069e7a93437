// The quality verdict's budget: within one second of a 10 s trial stopping, for four
// controllers at 120 Hz, on one core. Run: build/<preset>/tests/lmc_benchmarks
// --benchmark_filter=TrialQuality
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/hand/reference_poses.h"
#include "core/io/layout_json.h"
#include "core/session/trial_quality.h"

namespace {

using namespace lmc;

// A wrist flexing back and forth, seen by the four controllers of paper-initial at 120 Hz.
LmcRecording wrist_trial(const Layout& layout, double seconds) {
  const HandModel model;
  LmcRecording rec;
  for (int d = 0; d < 4; ++d) {
    const auto& dev = layout.devices[static_cast<size_t>(d)];
    const Eigen::Matrix3d rt = dev.pose.rotation().transpose();
    const Eigen::Vector3d shift = dev.pose.translation() + dev.offset_mm;
    std::int64_t frame_id = 0;
    for (double t = 0.001 * d; t < seconds; t += 1.0 / 120.0) {
      HandJointAngles a;
      a.wrist_flexion_deg = 30.0 * std::sin(t);
      HandFrame f = model.pose(a, reference_placement(model, HandOrientation::kHorizontal, a));
      for (int i = 0; i < kNumHandPoints; ++i) {
        f.point(i) =
            (i == kPalmNormal || i == kPalmDirection) ? Vec3(rt * f.point(i)) : Vec3(rt * (f.point(i) - shift));
      }
      f.device_id = d + 1;
      f.frame_id = ++frame_id;
      f.timestamp_us = 1'000'000 + static_cast<std::int64_t>(t * 1e6);
      rec.rows.push_back(f);
    }
  }
  return rec;
}

void BM_TrialQualityTenSecondsFourControllers(benchmark::State& state) {
  const Layout layout = load_layout_or_preset("paper-initial");
  const LmcRecording rec = wrist_trial(layout, 10.0);
  RecorderSidecar sidecar;
  sidecar.trial = "Naiv_Wrist101";
  sidecar.status = "completed";
  QualityInputs in;
  in.recording = &rec;
  in.sidecar = &sidecar;
  in.layout = layout;
  in.planned_s = 10.0;
  in.rom = {RomExpectation{"wrist", 60.0}};
  for (auto _ : state) benchmark::DoNotOptimize(assess_trial(in));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TrialQualityTenSecondsFourControllers)->Unit(benchmark::kMillisecond);

}  // namespace
