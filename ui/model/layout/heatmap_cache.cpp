#include "ui/model/layout/heatmap_cache.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lmc::ui {

bool HeatmapRequest::same_sweep(const HeatmapRequest& o) const {
  if (device != o.device || finger != o.finger || mode != o.mode || cells != o.cells ||
      half_extent_mm != o.half_extent_mm || poses != o.poses) {
    return false;
  }
  if (layout.devices.size() != o.layout.devices.size()) return false;
  for (size_t i = 0; i < layout.devices.size(); ++i) {
    LayoutDevice a = layout.devices[i], b = o.layout.devices[i];
    if (static_cast<int>(i) == device) {
      a.pose.x_mm = b.pose.x_mm = 0;
      a.pose.z_mm = b.pose.z_mm = 0;
    }
    if (!(a.pose == b.pose) || a.offset_mm != b.offset_mm || !(a.sensor == b.sensor)) return false;
  }
  return true;
}

HeatmapGridPtr sweep_heatmap(const HeatmapRequest& req, int cells, std::stop_token stop,
                             JobChannel<HeatmapGridPtr>* channel, long long done_before, long long total) {
  static const std::vector<PreparedFrame> no_frames;
  const HeatmapSpec spec{req.device, req.finger, req.mode, cells, req.half_extent_mm};
  const auto row_done = [&](int rows) {
    if (channel != nullptr) channel->set_progress(done_before + static_cast<long long>(rows) * cells, total);
  };
  auto swept = sweep_placement_heatmap(
      req.layout,
      req.poses ? std::span<const PreparedFrame>(req.poses->prepared) : std::span<const PreparedFrame>(no_frames), spec,
      stop, row_done);
  if (!swept) return nullptr;
  auto grid = std::make_shared<HeatmapGrid>();
  static_cast<PlacementHeatmap&>(*grid) = std::move(*swept);
  return grid;
}

void HeatmapCache::request(const HeatmapRequest& request) {
  if (has_request_ && current_.same_sweep(request)) return;
  current_ = request;
  has_request_ = true;
  ++key_;
  error_.clear();
  job_.abandon_into(graveyard_);
  const std::uint64_t key = key_;
  job_.start([req = request, key](std::stop_token stop, JobChannel<HeatmapGridPtr>& ch) {
    const int full = std::max(4, req.cells);
    const int passes[3] = {std::max(4, full / 4), std::max(4, full / 2), full};
    long long total = 0;
    for (int p : passes) total += static_cast<long long>(p) * p;
    long long done = 0;
    for (int i = 0; i < 3; ++i) {
      if (i > 0 && passes[i] == passes[i - 1]) continue;
      ch.set_stage(i == 2 ? "Sweeping (full resolution)" : "Sweeping (preview)");
      HeatmapGridPtr g = sweep_heatmap(req, passes[i], stop, &ch, done, total);
      if (!g) return 0;
      auto published = std::make_shared<HeatmapGrid>(*g);
      published->fine = i == 2;
      published->key = key;
      ch.report(std::move(published));
      done += static_cast<long long>(passes[i]) * passes[i];
    }
    return 0;
  });
}

void HeatmapCache::clear() {
  job_.abandon_into(graveyard_);
  has_request_ = false;
  latest_.reset();
}

void HeatmapCache::pause() {
  if (!job_.running()) return;
  job_.abandon_into(graveyard_);
  has_request_ = false;
}

void HeatmapCache::poll() {
  for (auto& g : job_.drain_reports()) {
    if (g && g->key == key_) latest_ = g;
  }
  if (job_.state() == JobState::kFailed) error_ = job_.error();
  graveyard_.reap();
}

}  // namespace lmc::ui
