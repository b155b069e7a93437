// Live fused hand latency end to end (goal ≤ 5 ms from a device frame's arrival at the
// hub to the fused hand, at 4 controllers × 120 Hz on 2 cores): the simulated rig's frames, four
// controllers at 120 Hz, are handed to a LiveFusion (devices/fusion/live_fusion.h) at their real
// times by a producer thread, as the hub's device threads would; the worker ray-traces, filters
// and publishes on its own thread. Counters: the worker's latency percentiles over the run (ms),
// frames fused and frames dropped for display.
// Run: build/release/tests/lmc_benchmarks --benchmark_filter=LiveFusion
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "core/io/layout_json.h"
#include "devices/fusion/live_fusion.h"
#include "devices/sim/sim_rig.h"

namespace live_fusion_bench {

using namespace lmc;
using namespace lmc::devices;

// `seconds` of the simulated rig at 120 Hz per controller, as (time, frame with its slot number).
std::vector<std::pair<double, HandFrame>> rig_frames(const Layout& layout, double seconds) {
  SimConfig cfg;
  cfg.rate_min_hz = 120;
  cfg.rate_max_hz = 120;
  cfg.rate_wander = 0;
  cfg.motion = HandMotion::kIndexFlexion;
  const SimTrial trial = generate_sim_trial(layout, cfg, seconds);
  std::map<std::string, int> slot_of;
  for (size_t i = 0; i < trial.devices.size(); ++i) slot_of[trial.devices[i].serial] = static_cast<int>(i) + 1;
  std::vector<std::pair<double, HandFrame>> out;
  for (const SimEvent& e : trial.events) {
    if (!e.is_frame) continue;
    HandFrame f = e.frame.frame;
    f.device_id = slot_of.at(e.frame.serial);
    out.emplace_back(e.time_s, f);
  }
  return out;
}

void BM_LiveFusionLatencyAt4x120Hz(benchmark::State& state) {
  const Layout layout = load_layout_or_preset("paper-initial");
  const auto frames = rig_frames(layout, 2.0);
  LiveFusionStats last;
  for (auto _ : state) {
    LiveFusion live(layout);
    const auto t0 = std::chrono::steady_clock::now();
    for (const auto& [t, frame] : frames) {
      std::this_thread::sleep_until(
          t0 + std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(t)));
      live.tap(frame);
    }
    // Every frame fused or dropped before the figures are read.
    const auto total = static_cast<std::int64_t>(frames.size());
    while (live.stats().frames_fused + live.stats().frames_dropped + live.stats().frames_refused < total)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    last = live.stats();
  }
  state.counters["p50_ms"] = last.latency_p50_ms;
  state.counters["p95_ms"] = last.latency_p95_ms;
  state.counters["max_ms"] = last.latency_max_ms;
  state.counters["fused"] = static_cast<double>(last.frames_fused);
  state.counters["dropped"] = static_cast<double>(last.frames_dropped);
  state.SetLabel(std::to_string(frames.size()) + " frames over 2 s (4 × 120 Hz); latency over the last " +
                 std::to_string(last.window_frames));
}
BENCHMARK(BM_LiveFusionLatencyAt4x120Hz)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

}  // namespace live_fusion_bench
