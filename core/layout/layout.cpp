#include "core/layout/layout.h"

#include <algorithm>
#include <cmath>

#include <set>
#include <utility>
#include "core/common/error.h"

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

void set_device_model(LayoutDevice& device, const SensorSpec& spec) {
  device.model = spec.id;
  device.sensor = spec.sensor;
  device.footprint_mm = spec.footprint_mm.head<2>();
}

void set_all_models(Layout& layout, const SensorSpec& spec) {
  for (auto& d : layout.devices) set_device_model(d, spec);
}

void set_all_sensors(Layout& layout, const SensorModel& sensor) {
  for (auto& d : layout.devices) d.sensor = sensor;
}

void set_models_from_list(Layout& layout, const std::string& ids, const SensorCatalogue& catalogue) {
  std::vector<std::string> list;
  size_t start = 0;
  while (start <= ids.size()) {
    const size_t comma = std::min(ids.find(',', start), ids.size());
    list.push_back(ids.substr(start, comma - start));
    start = comma + 1;
  }
  const std::string where = "--models " + ids;
  if (list.size() != 1 && list.size() != layout.devices.size()) {
    throw Error(where + ": " + std::to_string(list.size()) + " models for " + std::to_string(layout.devices.size()) +
                " devices (give one for all, or one per device)");
  }
  for (size_t i = 0; i < layout.devices.size(); ++i) {
    const std::string& id = list.size() == 1 ? list.front() : list[i];
    set_device_model(layout.devices[i], catalogue.at(id, where));
  }
}

bool uniform_sensors(const Layout& layout) {
  for (const auto& d : layout.devices) {
    if (!(d.sensor == layout.devices.front().sensor)) return false;
  }
  return true;
}

const SensorModel& common_sensor(const Layout& layout) {
  static const SensorModel study;
  if (layout.devices.empty()) return study;
  for (const auto& d : layout.devices) {
    if (!(d.sensor == layout.devices.front().sensor)) {
      throw Error("layout \"" + layout.name + "\": device \"" + d.slot + "\" (model \"" + d.model +
                  "\") sees through another sensor model than \"" + layout.devices.front().slot +
                  "\"; this step models one sensor for the whole rig");
    }
  }
  return layout.devices.front().sensor;
}

std::string validate_layout(const Layout& layout) {
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
    if (d.model.empty()) return at + "/model: empty sensor model";
    if (const std::string problem = sensor_problem(d.sensor); !problem.empty()) {
      return at + "/overrides/" + problem + " (device \"" + d.slot + "\", model \"" + d.model + "\")";
    }
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
