#include "ui/model/heatmap_cache.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/visibility/device_view.h"
#include "core/visibility/visibility_kernel.h"
#include "core/visibility/visibility_params.h"

namespace lmc::ui {

bool HeatmapRequest::same_sweep(const HeatmapRequest& o) const {
  if (device != o.device || finger != o.finger || mode != o.mode || cells != o.cells ||
      half_extent_mm != o.half_extent_mm || poses != o.poses) {
    return false;
  }
  if (layout.devices.size() != o.layout.devices.size() || !(layout.sensor == o.layout.sensor)) return false;
  for (size_t i = 0; i < layout.devices.size(); ++i) {
    LayoutDevice a = layout.devices[i], b = o.layout.devices[i];
    if (static_cast<int>(i) == device) {
      a.pose.x_mm = b.pose.x_mm = 0;
      a.pose.z_mm = b.pose.z_mm = 0;
    }
    if (!(a.pose == b.pose) || a.offset_mm != b.offset_mm) return false;
  }
  return true;
}

HeatmapGridPtr sweep_heatmap(const HeatmapRequest& req, int cells, std::stop_token stop,
                             JobChannel<HeatmapGridPtr>* channel, long long done_before, long long total) {
  auto grid = std::make_shared<HeatmapGrid>();
  grid->nx = grid->nz = cells;
  grid->x_lo_mm = grid->z_lo_mm = -req.half_extent_mm;
  grid->x_hi_mm = grid->z_hi_mm = req.half_extent_mm;
  grid->device = req.device;
  grid->finger = req.finger;
  grid->mode = req.mode;
  grid->value.assign(static_cast<size_t>(cells) * static_cast<size_t>(cells), std::numeric_limits<float>::quiet_NaN());
  if (!req.poses || req.device < 0 || req.device >= req.layout.device_count()) return grid;
  const auto& frames = req.poses->prepared;
  const size_t n = frames.size();
  if (n == 0) return grid;
  const VisibilityLimits limits = make_limits(VisibilityParams::from_sensor(req.layout.sensor));

  // Fingers no other controller sees, per frame (only the "added" mode needs them).
  std::vector<FingerBits> missing(n, kAllFingersVisible);
  if (req.mode == HeatmapMode::kFramesAdded) {
    std::vector<FingerBits> column(n);
    std::vector<FingerBits> others(n, 0);
    for (int d = 0; d < req.layout.device_count(); ++d) {
      if (d == req.device) continue;
      device_visibility(DeviceView::from_device(req.layout.devices[static_cast<size_t>(d)]), frames, limits, column);
      for (size_t j = 0; j < n; ++j) others[j] |= column[j];
      if (stop.stop_requested()) return nullptr;
    }
    for (size_t j = 0; j < n; ++j) missing[j] = static_cast<FingerBits>(~others[j] & kAllFingersVisible);
  }
  const FingerBits want = req.finger < 0 ? kAllFingersVisible : static_cast<FingerBits>(1u << req.finger);

  LayoutDevice dev = req.layout.devices[static_cast<size_t>(req.device)];
  double lo = 1.0, hi = 0.0;
  for (int iz = 0; iz < cells; ++iz) {
    if (stop.stop_requested()) return nullptr;
    for (int ix = 0; ix < cells; ++ix) {
      // The device origin (pose + offset) stands over the cell centre.
      dev.pose.x_mm = grid->cell_x_mm(ix) - dev.offset_mm.x();
      dev.pose.z_mm = grid->cell_z_mm(iz) - dev.offset_mm.z();
      const DeviceView view = DeviceView::from_device(dev);
      long long count = 0;
      for (size_t j = 0; j < n; ++j) {
        const FingerBits bits = visible_fingers(frames[j], view, limits);
        if (req.mode == HeatmapMode::kShareVisible) {
          count += (bits & want) == want;
        } else {
          // Added: the wanted fingers that nobody else sees are all seen by this controller
          // (for "all": the frame leaves c_0 thanks to it).
          const FingerBits need = missing[j] & want;
          count += need != 0 && (bits & need) == need;
        }
      }
      const double share = static_cast<double>(count) / static_cast<double>(n);
      grid->value[static_cast<size_t>(iz * cells + ix)] = static_cast<float>(share);
      lo = std::min(lo, share);
      hi = std::max(hi, share);
    }
    if (channel != nullptr) channel->set_progress(done_before + static_cast<long long>(iz + 1) * cells, total);
  }
  grid->data_min = lo;
  grid->data_max = hi;
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

void HeatmapCache::poll() {
  for (auto& g : job_.drain_reports()) {
    if (g && g->key == key_) latest_ = g;
  }
  if (job_.state() == JobState::kFailed) error_ = job_.error();
  graveyard_.reap();
}

}  // namespace lmc::ui
