#include "devices/soak/grouped_fusion.h"

#include <algorithm>
#include <cmath>

namespace lmc::devices {

Layout layout_slice(const Layout& layout, int first, int count) {
  Layout out = layout;
  out.devices.assign(layout.devices.begin() + first, layout.devices.begin() + first + count);
  return out;
}

GroupedFusion::GroupedFusion(const Layout& layout, LiveFusionOptions options) : devices_(layout.device_count()) {
  for (int first = 0; first < layout.device_count(); first += kMaxDevices) {
    const int count = std::min(kMaxDevices, layout.device_count() - first);
    groups_.push_back(std::make_unique<LiveFusion>(layout_slice(layout, first, count), options));
  }
}

GroupedFusion::~GroupedFusion() {
  stop();
}

void GroupedFusion::tap(const HandFrame& frame) noexcept {
  if (frame.device_id < 1 || frame.device_id > devices_) return;
  const auto group = static_cast<size_t>((frame.device_id - 1) / kMaxDevices);
  if (group == 0) {
    groups_[0]->tap(frame);
    return;
  }
  HandFrame local = frame;
  local.device_id -= static_cast<int>(group) * kMaxDevices;
  groups_[group]->tap(local);
}

void GroupedFusion::stop() {
  for (auto& g : groups_) g->stop();
}

LiveFusionStats GroupedFusion::stats() const {
  LiveFusionStats sum;
  for (const auto& g : groups_) {
    const LiveFusionStats s = g->stats();
    sum.frames_tapped += s.frames_tapped;
    sum.frames_fused += s.frames_fused;
    sum.frames_dropped += s.frames_dropped;
    sum.frames_refused += s.frames_refused;
    sum.published += s.published;
    sum.window_frames += s.window_frames;
    const auto worst = [](double a, double b) { return std::isnan(a) ? b : std::isnan(b) ? a : std::max(a, b); };
    sum.latency_p50_ms = worst(sum.latency_p50_ms, s.latency_p50_ms);
    sum.latency_p95_ms = worst(sum.latency_p95_ms, s.latency_p95_ms);
    sum.latency_max_ms = worst(sum.latency_max_ms, s.latency_max_ms);
  }
  return sum;
}

}  // namespace lmc::devices
