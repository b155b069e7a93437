#include "core/optimise/search_space.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

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

std::string SearchSpace::validate() const {
  for (int k = 0; k < kNumPoseParams; ++k) {
    const auto& b = bounds[static_cast<size_t>(k)];
    if (!std::isfinite(b.min) || !std::isfinite(b.max))
      return std::string("bounds for ") + pose_param_name(k) + ": not finite";
    if (b.min > b.max) return std::string("bounds for ") + pose_param_name(k) + ": min > max";
    const double limit = k < 3 ? 10000.0 : 360.0;
    if (std::abs(b.min) > limit || std::abs(b.max) > limit) {
      return std::string("bounds for ") + pose_param_name(k) + (k < 3 ? ": beyond ±10 m" : ": beyond ±360°");
    }
  }
  return {};
}

SearchSpace parse_search_bounds(const std::string& spec) {
  SearchSpace space;
  space.free.fill(false);
  const ErrorLocation where("--bounds");
  size_t start = 0;
  int item = 0;
  while (start <= spec.size()) {
    const size_t comma = spec.find(',', start);
    const std::string part = spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    ++item;
    const size_t eq = part.find('=');
    const size_t colon = part.find(':', eq == std::string::npos ? 0 : eq);
    if (eq == std::string::npos || colon == std::string::npos) {
      throw Error(ErrorLocation("--bounds", 0, static_cast<long>(start + 1)),
                  "item " + std::to_string(item) + " \"" + part + "\" must look like name=min:max (e.g. x=-400:400)");
    }
    const std::string name = part.substr(0, eq);
    const int k = pose_param_from_name(name.c_str());
    if (k < 0) {
      throw Error(ErrorLocation("--bounds", 0, static_cast<long>(start + 1)),
                  "unknown parameter \"" + name + "\" (x, y, z, rx, ry, rz)");
    }
    auto number = [&](const std::string& text) {
      size_t used = 0;
      double v = 0;
      try {
        v = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != text.size() || !std::isfinite(v)) {
        throw Error(ErrorLocation("--bounds", 0, static_cast<long>(start + 1)),
                    "\"" + text + "\" in \"" + part + "\" is not a number");
      }
      return v;
    };
    const double lo = number(part.substr(eq + 1, colon - eq - 1));
    const double hi = number(part.substr(colon + 1));
    if (lo > hi) {
      throw Error(ErrorLocation("--bounds", 0, static_cast<long>(start + 1)),
                  "\"" + part + "\": min is greater than max");
    }
    space.free[static_cast<size_t>(k)] = true;
    space.bounds[static_cast<size_t>(k)] = {lo, hi};
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (const std::string problem = space.validate(); !problem.empty()) throw Error(where, problem);
  return space;
}

std::string format_search_bounds(const SearchSpace& space) {
  std::string out;
  for (int k = 0; k < kNumPoseParams; ++k) {
    const auto kk = static_cast<size_t>(k);
    if (!space.free[kk]) continue;
    if (!out.empty()) out += ',';
    // %.17g: every double reads back as itself (and 360 is still written "360").
    char item[96];
    std::snprintf(item, sizeof item, "%s=%.17g:%.17g", pose_param_name(k), space.bounds[kk].min, space.bounds[kk].max);
    out += item;
  }
  return out;
}

Layout default_start_layout(int devices, const SensorModel& sensor) {
  Layout l;
  l.name = "start";
  for (int d = 0; d < devices; ++d) {
    LayoutDevice dev;
    dev.sensor = sensor;
    dev.slot = "LMC" + std::to_string(d + 1);
    dev.pose.x_mm = (d - 0.5 * (devices - 1)) * 120.0;
    l.devices.push_back(dev);
  }
  return l;
}

SearchSpace table_search_space() {
  SearchSpace s;
  const double half = kTableHalfExtentMm - 40.0;  // half a controller's 80 mm length
  s.bounds[0] = {-half, half};
  s.bounds[2] = {-half, half};
  return s;
}

}  // namespace lmc
