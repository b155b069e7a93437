// Live fused hand latency (goal ≤ 5 ms from a device frame's arrival to the fused hand
// at 4 controllers × 120 Hz on 2 cores): one OnlineFusion::add() (ray tracing, weights,
// realignment, 90 Kalman lanes) plus current(), devices taking turns as a hub would deliver them.
// Run: build/<release>/tests/lmc_benchmarks --benchmark_filter=OnlineFusion
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "core/hand/hand_model.h"
#include "core/hand/reference_poses.h"
#include "core/io/layout_json.h"
#include "core/processing/online_fusion.h"

namespace online_fusion_bench {

using namespace lmc;

// One second of a flexing index finger seen by every device of `layout`, 120 Hz, device frames:
// frames[k * devices + d].
std::vector<HandFrame> device_frames(const Layout& layout) {
  const HandModel model;
  std::vector<HandFrame> out;
  for (int k = 0; k < 120; ++k) {
    const double progress = 0.5 * (1.0 - std::cos(2.0 * M_PI * k / 120.0));
    const HandJointAngles a = motion_angles(HandMotion::kIndexFlexion, progress);
    const HandFrame world = model.pose(a, reference_placement(model, HandOrientation::kHorizontal, a));
    for (const auto& dev : layout.devices) {
      const Eigen::Matrix3d rt = dev.pose.rotation().transpose();
      const Eigen::Vector3d shift = dev.pose.translation() + dev.offset_mm;
      HandFrame f = world;
      f.hand_present = true;
      for (int i = 0; i < kNumHandPoints; ++i) {
        f.point(i) =
            (i == kPalmNormal || i == kPalmDirection) ? Vec3(rt * world.point(i)) : Vec3(rt * (world.point(i) - shift));
      }
      out.push_back(f);
    }
  }
  return out;
}

void BM_OnlineFusionAddAndCurrent(benchmark::State& state) {
  const Layout layout = load_layout_or_preset("paper-initial");
  const std::vector<HandFrame> frames = device_frames(layout);
  const int devices = layout.device_count();
  OnlineFusion fusion(layout);
  size_t j = 0;
  double t = 0.0;
  for (auto _ : state) {
    const int d = static_cast<int>(j % static_cast<size_t>(devices));
    fusion.add(frames[j], d, t);
    FusedHand h = fusion.current();
    benchmark::DoNotOptimize(h);
    t += 1.0 / (120.0 * devices);  // 4 × 120 Hz interleaved
    j = (j + 1) % frames.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("one device frame: add() + current()");
}
BENCHMARK(BM_OnlineFusionAddAndCurrent)->Unit(benchmark::kMicrosecond);

}  // namespace online_fusion_bench
