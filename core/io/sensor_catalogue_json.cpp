#include "core/io/sensor_catalogue_json.h"

#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "core/common/paths.h"
#include "core/io/json_checked.h"

namespace lmc {
namespace {

Eigen::Vector3d read_vec3(const JsonReader& r, const char* what) {
  if (r.array_size() != 3) r.fail(std::string("expected [x, y, z] ") + what);
  return {r.at(size_t{0}).number(), r.at(size_t{1}).number(), r.at(size_t{2}).number()};
}

SensorSpec read_model(const JsonReader& m) {
  m.only_keys({"id", "name", "fov_long_deg", "fov_short_deg", "range_near_mm", "range_far_mm", "axis_cut_mm",
               "frame_rate_hz", "footprint_mm", "origin_in_case_mm", "leapc_product_ids", "position_noise_sd_mm",
               "sources"});
  SensorSpec spec;
  spec.id = m.string("id");
  if (spec.id.empty() || spec.id.size() > 32) m.at("id").fail("must be 1–32 characters");
  for (char c : spec.id) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) {
      m.at("id").fail("only letters, digits, '_' and '-' are allowed");
    }
  }
  spec.name = m.string("name");
  spec.sensor.fov_long_deg = m.number("fov_long_deg");
  spec.sensor.fov_short_deg = m.number("fov_short_deg");
  spec.sensor.range_near_mm = m.number("range_near_mm");
  spec.sensor.range_mm = m.number("range_far_mm");
  spec.sensor.axis_cut_mm = m.number("axis_cut_mm");
  if (std::string problem = sensor_problem(spec.sensor); !problem.empty()) {
    // The catalogue calls the far range range_far_mm; sensor_problem speaks of range_mm.
    const auto colon = problem.find(": ");
    std::string field = problem.substr(0, colon);
    if (field == "range_mm") field = "range_far_mm";
    m.at(field.c_str()).fail(problem.substr(colon + 2));
  }
  spec.frame_rate_hz = m.number("frame_rate_hz");
  if (spec.frame_rate_hz <= 0 || spec.frame_rate_hz > 1000) m.at("frame_rate_hz").fail("must be in (0, 1000]");
  spec.footprint_mm = read_vec3(m.at("footprint_mm"), "in mm (width, height, depth)");
  if ((spec.footprint_mm.array() <= 0).any() || (spec.footprint_mm.array() > 1000).any()) {
    m.at("footprint_mm").fail("every side must be in (0, 1000] mm");
  }
  spec.origin_in_case_mm = read_vec3(m.at("origin_in_case_mm"), "in mm");
  if ((spec.origin_in_case_mm.array().abs() > 1000).any()) m.at("origin_in_case_mm").fail("beyond ±1000 mm");
  const auto pids = m.at("leapc_product_ids");
  for (size_t i = 0; i < pids.array_size(); ++i) {
    const int pid = pids.at(i).integer();
    if (pid < 0 || pid > 0xFFFF) pids.at(i).fail("a product id is 0 to 65535");
    spec.leapc_product_ids.push_back(static_cast<std::uint32_t>(pid));
  }
  // Optional: a model without a published figure leaves it out (a null is a mistake, not "none").
  if (m.json().contains("position_noise_sd_mm")) {
    const auto sd = m.at("position_noise_sd_mm");
    if (!sd.json().is_number() || !(sd.number() >= 0)) {
      sd.fail("model \"" + spec.id + "\": position_noise_sd_mm must be a number ≥ 0 (mm), not " + sd.json().dump());
    }
    spec.position_noise_sd_mm = sd.number();
  }
  const auto sources = m.at("sources");
  sources.only_keys({"fov", "range", "axis_cut", "frame_rate", "footprint", "origin", "product_ids", "position_noise"});
  for (const char* key : {"fov", "range", "axis_cut", "frame_rate", "footprint", "origin", "product_ids"}) {
    if (sources.string(key).empty()) sources.at(key).fail("every figure needs its source");
  }
  if (spec.position_noise_sd_mm && sources.string("position_noise").empty()) {
    sources.at("position_noise").fail("every figure needs its source");
  }
  if (!spec.position_noise_sd_mm && sources.has("position_noise")) {
    sources.at("position_noise")
        .fail("a source for position_noise_sd_mm, which model \"" + spec.id + "\" does not give");
  }
  return spec;
}

}  // namespace

SensorCatalogue sensor_catalogue_from_json(const nlohmann::json& j, const std::string& source) {
  JsonReader root(j, source);
  root.only_keys({"format", "about", "models"});
  const int format = root.at("format").integer();
  if (format != kSensorCatalogueFormatVersion) {
    root.at("format").fail("unsupported sensor catalogue format " + std::to_string(format) + " (this build reads " +
                           std::to_string(kSensorCatalogueFormatVersion) + ")");
  }
  SensorCatalogue cat;
  cat.source = source;
  const auto models = root.at("models");
  std::set<std::string> ids;
  for (size_t i = 0; i < models.array_size(); ++i) {
    SensorSpec spec = read_model(models.at(i));
    if (!ids.insert(spec.id).second) models.at(i).at("id").fail("duplicate model id \"" + spec.id + "\"");
    cat.models.push_back(std::move(spec));
  }
  if (!cat.find(kStudySensorId)) {
    models.fail(std::string("the catalogue must hold the study's model \"") + kStudySensorId + "\"");
  }
  return cat;
}

SensorCatalogue load_sensor_catalogue(const std::filesystem::path& path) {
  return sensor_catalogue_from_json(read_json_file(path), path.string());
}

const SensorCatalogue& sensor_catalogue() {
  static const SensorCatalogue catalogue = load_sensor_catalogue(assets_dir() / "sensors" / "sensors.json");
  return catalogue;
}

}  // namespace lmc
