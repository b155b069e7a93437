#include "core/optimise/search_space.h"

#include "core/common/error.h"

namespace lmc {

void SearchSpace::lock_device(int device, bool on) {
  for (int k = 0; k < kNumPoseParams; ++k) lock_param(device, k, on);
}

void SearchSpace::lock_param(int device, int param, bool on) {
  if (device < 0 || param < 0 || param >= kNumPoseParams) return;
  if (static_cast<int>(locked.size()) <= device) locked.resize(static_cast<size_t>(device) + 1, {});
  locked[static_cast<size_t>(device)][static_cast<size_t>(param)] = on;
}

bool SearchSpace::is_locked(int device, int param) const {
  if (device < 0 || device >= static_cast<int>(locked.size())) return false;
  return locked[static_cast<size_t>(device)][static_cast<size_t>(param)];
}

bool SearchSpace::device_fully_locked(int device) const {
  for (int k = 0; k < kNumPoseParams; ++k) {
    if (free[static_cast<size_t>(k)] && !is_locked(device, k)) return false;
  }
  return true;
}

std::vector<std::pair<int, int>> SearchSpace::dimensions(int devices) const {
  std::vector<std::pair<int, int>> dims;
  for (int d = 0; d < devices; ++d) {
    for (int k = 0; k < kNumPoseParams; ++k) {
      if (free[static_cast<size_t>(k)] && !is_locked(d, k)) dims.emplace_back(d, k);
    }
  }
  return dims;
}

std::string SearchSpace::validate() const { return {}; }

SearchSpace parse_search_bounds(const std::string&) { return {}; }

Layout default_start_layout(int devices, const SensorModel& sensor) {
  Layout l;
  l.name = "start";
  l.sensor = sensor;
  for (int d = 0; d < devices; ++d) {
    LayoutDevice dev;
    dev.slot = "LMC" + std::to_string(d + 1);
    dev.pose.x_mm = (d - 0.5 * (devices - 1)) * 120.0;
    l.devices.push_back(dev);
  }
  return l;
}

}  // namespace lmc
