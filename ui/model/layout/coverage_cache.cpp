#include "ui/model/layout/coverage_cache.h"

#include <chrono>
#include <thread>

#include "core/visibility/device_view.h"
#include "core/visibility/visibility_params.h"

namespace lmc::ui {

ColumnKey column_key(const LayoutDevice& device, const SensorModel& sensor, std::uint64_t pose_set_version) {
  return {device.pose, {device.offset_mm.x(), device.offset_mm.y(), device.offset_mm.z()}, sensor, pose_set_version};
}

CoverageSnapshotPtr compute_coverage_snapshot(const Layout& layout, const PoseSetPtr& poses,
                                              const CoverageSnapshotPtr& previous, std::stop_token stop) {
  auto snap = std::make_shared<CoverageSnapshot>();
  if (!poses) return snap;
  snap->pose_set_version = poses->version;
  for (const LayoutDevice& dev : layout.devices) {
    const VisibilityLimits limits = make_limits(VisibilityParams::from_sensor(dev.sensor));
    const ColumnKey key = column_key(dev, dev.sensor, poses->version);
    BitColumn column;
    if (previous) {
      for (size_t i = 0; i < previous->keys.size(); ++i) {
        if (previous->keys[i] == key) column = previous->columns[i];
      }
    }
    if (!column) {
      if (stop.stop_requested()) return nullptr;
      auto bits = std::make_shared<std::vector<FingerBits>>(poses->prepared.size());
      device_visibility(DeviceView::from_device(dev), poses->prepared, limits, *bits);
      column = std::move(bits);
      ++snap->columns_computed;
    }
    snap->keys.push_back(key);
    snap->columns.push_back(std::move(column));
  }
  std::vector<std::span<const FingerBits>> spans;
  for (const auto& c : snap->columns) spans.emplace_back(*c);
  OrientationCoverage split = coverage_by_orientation(spans, poses->horizontal, poses->vertical);
  snap->all = std::move(split.all);
  snap->horizontal = std::move(split.horizontal);
  snap->vertical = std::move(split.vertical);
  return snap;
}

void CoverageCache::request(const Layout& layout, const PoseSetPtr& poses) {
  if (!poses) return;
  std::vector<ColumnKey> keys;
  keys.reserve(layout.devices.size());
  for (const auto& d : layout.devices) keys.push_back(column_key(d, d.sensor, poses->version));
  if (keys == requested_keys_ && requested_poses_ == poses) return;
  requested_keys_ = std::move(keys);
  requested_layout_ = layout;
  requested_poses_ = poses;
  pending_ = true;
  if (!job_.running()) start_pending();
}

void CoverageCache::start_pending() {
  if (!pending_) return;
  pending_ = false;
  job_.start(
      [layout = requested_layout_, poses = requested_poses_, previous = latest_](
          std::stop_token stop, JobChannel<int>&) { return compute_coverage_snapshot(layout, poses, previous, stop); });
}

void CoverageCache::poll() {
  const JobState s = job_.state();
  if (s == JobState::kCompleted) {
    if (auto r = job_.result(); r && *r && *r != latest_) latest_ = *r;
    error_.clear();
  } else if (s == JobState::kFailed) {
    error_ = job_.error();
  }
  if (!job_.running()) start_pending();
}

void CoverageCache::wait() {
  for (;;) {
    poll();
    if (!busy()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  poll();
}

bool CoverageCache::up_to_date() const {
  return latest_ && !busy() && latest_->keys == requested_keys_;
}

}  // namespace lmc::ui
