#include "core/io/layout_json.h"

#include <nlohmann/json.hpp>
#include <string_view>

#include "core/common/paths.h"
#include "core/io/atomic_write.h"
#include "core/io/json_checked.h"

namespace lmc {

Layout layout_from_json(const nlohmann::json& j, const std::string& source) {
  JsonReader root(j, source);
  root.only_keys({"format", "name", "description", "sensor", "devices"});
  const int format = root.at("format").integer();
  if (format != kLayoutFormatVersion) {
    root.at("format").fail("unsupported layout format " + std::to_string(format) + " (this build reads " +
                           std::to_string(kLayoutFormatVersion) + ")");
  }
  Layout layout;
  layout.name = root.string_or("name", "");
  layout.description = root.string_or("description", "");
  if (root.has("sensor")) {
    const auto s = root.at("sensor");
    s.only_keys({"range_mm", "fov_long_deg", "fov_short_deg"});
    layout.sensor.range_mm = s.number_or("range_mm", layout.sensor.range_mm);
    layout.sensor.fov_long_deg = s.number_or("fov_long_deg", layout.sensor.fov_long_deg);
    layout.sensor.fov_short_deg = s.number_or("fov_short_deg", layout.sensor.fov_short_deg);
  }
  const auto devices = root.at("devices");
  const size_t n = devices.array_size();
  for (size_t i = 0; i < n; ++i) {
    const auto d = devices.at(i);
    d.only_keys({"slot", "serial", "pose", "offset"});
    LayoutDevice dev;
    dev.slot = d.string("slot");
    if (d.has("serial")) dev.serial = d.string("serial");
    const auto pose = d.at("pose");
    pose.only_keys({"x", "y", "z", "rx", "ry", "rz"});
    for (int k = 0; k < kNumPoseParams; ++k) {
      const char* key = pose_param_name(k);
      // The study's layouts vary x, z, rx, ry with the controller flat on the table: y and rz may
      // be left out (0). A key that is present must hold a number (null is not 0).
      const bool optional = std::string_view(key) == "y" || std::string_view(key) == "rz";
      dev.pose.set(k, optional && !pose.json().contains(key) ? 0.0 : pose.number(key));
    }
    if (d.has("offset")) {
      const auto off = d.at("offset");
      if (off.array_size() != 3) off.fail("expected [x, y, z] in mm");
      for (size_t k = 0; k < 3; ++k) dev.offset_mm[static_cast<int>(k)] = off.at(k).number();
    }
    layout.devices.push_back(std::move(dev));
  }
  if (const std::string problem = validate_layout(layout); !problem.empty()) {
    const auto colon = problem.find(": ");
    throw Error(ErrorLocation{source, 0, 0, problem.substr(0, colon)}, problem.substr(colon + 2));
  }
  return layout;
}

nlohmann::json layout_to_json(const Layout& layout) {
  nlohmann::json j;
  j["format"] = kLayoutFormatVersion;
  j["name"] = layout.name;
  if (!layout.description.empty()) j["description"] = layout.description;
  j["sensor"] = {{"range_mm", layout.sensor.range_mm},
                 {"fov_long_deg", layout.sensor.fov_long_deg},
                 {"fov_short_deg", layout.sensor.fov_short_deg}};
  auto& devs = j["devices"] = nlohmann::json::array();
  for (const auto& d : layout.devices) {
    nlohmann::json dj;
    dj["slot"] = d.slot;
    dj["serial"] = d.serial ? nlohmann::json(*d.serial) : nlohmann::json(nullptr);
    nlohmann::json pose = nlohmann::json::object();
    for (int k = 0; k < kNumPoseParams; ++k) pose[pose_param_name(k)] = d.pose.get(k);
    dj["pose"] = pose;
    dj["offset"] = {d.offset_mm.x(), d.offset_mm.y(), d.offset_mm.z()};
    devs.push_back(std::move(dj));
  }
  return j;
}

Layout load_layout(const std::filesystem::path& path) {
  return layout_from_json(read_json_file(path), path.string());
}

void save_layout(const Layout& layout, const std::filesystem::path& path) {
  if (const std::string problem = validate_layout(layout); !problem.empty()) {
    throw Error(ErrorLocation{path.string()}, "refusing to save an invalid layout: " + problem);
  }
  write_file_atomically(path, layout_to_json(layout).dump(2) + "\n");
}

Layout load_layout_or_preset(const std::string& name_or_path) {
  std::filesystem::path p(name_or_path);
  if (std::filesystem::exists(p)) return load_layout(p);
  const bool looks_like_preset = name_or_path.find('/') == std::string::npos &&
                                 name_or_path.find('\\') == std::string::npos &&
                                 name_or_path.find("..") == std::string::npos;
  if (looks_like_preset) {
    auto preset = assets_dir() / "layouts" / (name_or_path + ".json");
    if (std::filesystem::exists(preset)) return load_layout(preset);
  }
  throw Error(ErrorLocation{name_or_path},
              "no such layout file or preset (presets: paper-initial, paper-optimized, "
              "paper-optimized-as-processed)");
}

}  // namespace lmc
