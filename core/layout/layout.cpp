#include "core/layout/layout.h"

#include <cmath>
#include <set>
#include <utility>

namespace lmc {

int Layout::find_slot(const std::string& slot) const {
  for (size_t i = 0; i < devices.size(); ++i) {
    if (devices[i].slot == slot) return static_cast<int>(i);
  }
  return -1;
}

int Layout::find_serial(const std::string& serial) const {
  for (size_t i = 0; i < devices.size(); ++i) {
    if (devices[i].serial && *devices[i].serial == serial) return static_cast<int>(i);
  }
  return -1;
}

std::string validate_layout(const Layout& layout) {
  const auto& s = layout.sensor;
  if (!std::isfinite(s.range_mm) || s.range_mm <= 0 || s.range_mm > 5000) {
    return "/sensor/range_mm: must be a finite number in (0, 5000]";
  }
  if (!std::isfinite(s.fov_long_deg) || s.fov_long_deg <= 0 || s.fov_long_deg >= 180) {
    return "/sensor/fov_long_deg: must be in (0, 180)";
  }
  if (!std::isfinite(s.fov_short_deg) || s.fov_short_deg <= 0 || s.fov_short_deg >= 180) {
    return "/sensor/fov_short_deg: must be in (0, 180)";
  }
  if (layout.devices.empty() || layout.device_count() > kMaxDevices) {
    return "/devices: a layout holds 1 to " + std::to_string(kMaxDevices) + " devices, this one has " +
           std::to_string(layout.devices.size());
  }
  std::set<std::string> slots, serials;
  for (size_t i = 0; i < layout.devices.size(); ++i) {
    const auto& d = layout.devices[i];
    const std::string at = "/devices/" + std::to_string(i);
    if (d.slot.empty()) return at + "/slot: empty slot name";
    if (d.slot.size() > 32) return at + "/slot: longer than 32 characters";
    for (char c : d.slot) {
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) {
        return at + "/slot: only letters, digits, '_' and '-' are allowed";
      }
    }
    if (!slots.insert(d.slot).second) return at + "/slot: duplicate slot \"" + d.slot + "\"";
    if (d.serial) {
      if (d.serial->empty() || d.serial->size() > 64) return at + "/serial: must be 1–64 characters";
      for (char c : *d.serial) {
        if (!std::isprint(static_cast<unsigned char>(c))) return at + "/serial: unprintable character";
      }
      if (!serials.insert(*d.serial).second) return at + "/serial: duplicate serial \"" + *d.serial + "\"";
    }
    for (int k = 0; k < kNumPoseParams; ++k) {
      const double v = d.pose.get(k);
      if (!std::isfinite(v)) return at + "/pose/" + pose_param_name(k) + ": not a finite number";
      if (k < 3 && std::abs(v) > 10000) return at + "/pose/" + pose_param_name(k) + ": beyond ±10 m";
      if (k >= 3 && std::abs(v) > 360) return at + "/pose/" + pose_param_name(k) + ": beyond ±360°";
    }
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(d.offset_mm[k]) || std::abs(d.offset_mm[k]) > 1000) {
        return at + "/offset/" + std::to_string(k) + ": must be a finite number within ±1000 mm";
      }
    }
  }
  return {};
}

Layout square_layout(std::string name) {
  Layout l;
  l.name = std::move(name);
  const double xs[4] = {-60, 60, -60, 60};
  const double zs[4] = {60, 60, -60, -60};
  for (int i = 0; i < 4; ++i) {
    LayoutDevice d;
    d.slot = "LMC" + std::to_string(i + 1);
    d.pose.x_mm = xs[i];
    d.pose.z_mm = zs[i];
    l.devices.push_back(d);
  }
  return l;
}

}  // namespace lmc
