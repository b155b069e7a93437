#include "core/io/layout_json.h"

#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

#include "core/common/paths.h"
#include "core/io/atomic_write.h"
#include "core/io/json_checked.h"

namespace lmc {

namespace {

constexpr const char* kOverrideKeys[] = {"range_mm", "range_near_mm", "fov_long_deg", "fov_short_deg", "axis_cut_mm"};

SensorOverrides read_overrides(const JsonReader& o) {
  o.only_keys({"range_mm", "range_near_mm", "fov_long_deg", "fov_short_deg", "axis_cut_mm"});
  SensorOverrides out;
  if (o.has("range_mm")) out.range_mm = o.number("range_mm");
  if (o.has("range_near_mm")) out.range_near_mm = o.number("range_near_mm");
  if (o.has("fov_long_deg")) out.fov_long_deg = o.number("fov_long_deg");
  if (o.has("fov_short_deg")) out.fov_short_deg = o.number("fov_short_deg");
  if (o.has("axis_cut_mm")) out.axis_cut_mm = o.number("axis_cut_mm");
  return out;
}

nlohmann::json overrides_json(const SensorOverrides& o) {
  nlohmann::json j = nlohmann::json::object();
  const std::optional<double> values[] = {o.range_mm, o.range_near_mm, o.fov_long_deg, o.fov_short_deg, o.axis_cut_mm};
  for (size_t k = 0; k < std::size(values); ++k) {
    if (values[k]) j[kOverrideKeys[k]] = *values[k];
  }
  return j;
}

}  // namespace

Layout layout_from_json(const nlohmann::json& j, const std::string& source, const SensorCatalogue& catalogue) {
  JsonReader root(j, source);
  const int format = root.at("format").integer();
  if (format != 1 && format != kLayoutFormatVersion) {
    root.at("format").fail("unsupported layout format " + std::to_string(format) + " (this build reads 1 and " +
                           std::to_string(kLayoutFormatVersion) + ")");
  }
  const bool v1 = format == 1;
  if (v1) {
    root.only_keys({"format", "name", "description", "sensor", "devices"});
  } else {
    root.only_keys({"format", "name", "description", "devices"});
  }
  Layout layout;
  layout.name = root.string_or("name", "");
  layout.description = root.string_or("description", "");
  // Version 1: one sensor for every device, named by the catalogue model it equals.
  SensorModel v1_sensor;
  const SensorSpec* v1_spec = catalogue.find(kStudySensorId);
  if (v1) {
    if (root.has("sensor")) {
      const auto s = root.at("sensor");
      s.only_keys({"range_mm", "fov_long_deg", "fov_short_deg"});
      v1_sensor.range_mm = s.number_or("range_mm", v1_sensor.range_mm);
      v1_sensor.fov_long_deg = s.number_or("fov_long_deg", v1_sensor.fov_long_deg);
      v1_sensor.fov_short_deg = s.number_or("fov_short_deg", v1_sensor.fov_short_deg);
    }
    if (const SensorSpec* m = catalogue.matching(v1_sensor)) v1_spec = m;
  }
  const auto devices = root.at("devices");
  const size_t n = devices.array_size();
  for (size_t i = 0; i < n; ++i) {
    const auto d = devices.at(i);
    if (v1) {
      d.only_keys({"slot", "serial", "pose", "offset"});
    } else {
      d.only_keys({"slot", "serial", "model", "overrides", "pose", "offset"});
    }
    LayoutDevice dev;
    dev.slot = d.string("slot");
    if (d.has("serial")) dev.serial = d.string("serial");
    if (v1) {
      if (v1_spec) set_device_model(dev, *v1_spec);
      dev.sensor = v1_sensor;
    } else {
      dev.model = d.string("model");
      const SensorSpec* spec = catalogue.find(dev.model);
      if (!spec) {
        d.at("model").fail("device \"" + dev.slot + "\" names unknown sensor model \"" + dev.model +
                           "\" (known models: " + catalogue.known_ids() + ")");
      }
      set_device_model(dev, *spec);
      if (d.has("overrides")) dev.sensor = apply_overrides(spec->sensor, read_overrides(d.at("overrides")));
    }
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
    std::string path = problem.substr(0, colon);
    // A version-1 file holds the sensor once, at /sensor.
    if (const auto at = path.find("/overrides/"); v1 && at != std::string::npos)
      path = "/sensor/" + path.substr(at + 11);
    throw Error(ErrorLocation{source, 0, 0, path}, problem.substr(colon + 2));
  }
  return layout;
}

nlohmann::json layout_to_json(const Layout& layout, const SensorCatalogue& catalogue) {
  nlohmann::json j;
  j["format"] = kLayoutFormatVersion;
  j["name"] = layout.name;
  if (!layout.description.empty()) j["description"] = layout.description;
  auto& devs = j["devices"] = nlohmann::json::array();
  for (const auto& d : layout.devices) {
    nlohmann::json dj;
    dj["slot"] = d.slot;
    dj["serial"] = d.serial ? nlohmann::json(*d.serial) : nlohmann::json(nullptr);
    const SensorSpec& spec = catalogue.at(d.model, "layout \"" + layout.name + "\", device \"" + d.slot + "\"");
    dj["model"] = d.model;
    if (const SensorOverrides o = overrides_between(spec.sensor, d.sensor); !o.empty())
      dj["overrides"] = overrides_json(o);
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
