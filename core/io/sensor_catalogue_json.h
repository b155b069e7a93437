#pragma once
// The sensor catalogue file (assets/sensors/sensors.json, docs/formats.md):
//   { "format": 1, "about": "...",
//     "models": [ { "id": "lmc2", "name": "Leap Motion Controller 2",
//                   "fov_long_deg": 160, "fov_short_deg": 160, "range_near_mm": 100, "range_far_mm": 1100,
//                   "axis_cut_mm": 666, "frame_rate_hz": 120, "footprint_mm": [84, 20, 12],
//                   "origin_in_case_mm": [0, 12, 0], "leapc_product_ids": [4614], "position_noise_sd_mm": 0.6,
//                   "sources": { "fov": "...", "range": "...", "axis_cut": "...", "frame_rate": "...",
//                                "footprint": "...", "origin": "...", "product_ids": "...",
//                                "position_noise": "..." } }, ... ] }
// Every figure must name its source: a model without one of the seven "sources" is refused, and so is
// one with position_noise_sd_mm (optional, a number ≥ 0) but no "position_noise" source.
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "core/layout/sensor_catalogue.h"

namespace lmc {

inline constexpr int kSensorCatalogueFormatVersion = 1;

// Parses and validates; throws lmc::Error naming `source` and the JSON path of the problem (an
// unknown or missing field, a duplicate id, a figure without a source, an insane sensor model).
SensorCatalogue sensor_catalogue_from_json(const nlohmann::json& j, const std::string& source);
SensorCatalogue load_sensor_catalogue(const std::filesystem::path& path);

// The shipped catalogue, assets_dir()/sensors/sensors.json, read once (thread-safe). Throws
// lmc::Error naming the file and field when it is missing or malformed.
const SensorCatalogue& sensor_catalogue();

}  // namespace lmc
