#pragma once
// Layout files (assets/layouts/*.json, user layouts; docs/formats.md). Format version 2, written:
//   { "format": 2, "name": "...", "description": "...",
//     "devices": [ { "slot": "LMC1", "serial": "LP12345" | null, "model": "lmc2",
//                    "overrides": { "range_mm": 400 },            (optional: fields unlike the model's)
//                    "pose": { "x": 0, "y": 0, "z": 0, "rx": 0, "ry": 0, "rz": 0 },
//                    "offset": [0, 0, 0] }, ... ] }
// Version 1 (still read) has no model per device but one "sensor" { range_mm, fov_long_deg,
// fov_short_deg } for all: every device gets it, named by the catalogue model it equals ("study"
// for the study's values) or "study" with overrides. Pose in mm and degrees
// (docs/algorithms/frames.md); offset in mm, applied after the pose.
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "core/io/sensor_catalogue_json.h"
#include "core/layout/layout.h"

namespace lmc {

inline constexpr int kLayoutFormatVersion = 2;  // what is written; 1 is read too

// Parses and validates; throws lmc::Error naming `source` and the JSON path of the problem; a
// device naming a model the catalogue lacks is refused naming the device and the known models.
Layout layout_from_json(const nlohmann::json& j, const std::string& source,
                        const SensorCatalogue& catalogue = sensor_catalogue());
// Always version 2. Throws lmc::Error when a device names a model the catalogue lacks.
nlohmann::json layout_to_json(const Layout& layout, const SensorCatalogue& catalogue = sensor_catalogue());

Layout load_layout(const std::filesystem::path& path);
// Atomic (temporary file + rename). Throws lmc::Error when the layout is invalid or the write fails.
void save_layout(const Layout& layout, const std::filesystem::path& path);

// A layout by preset name ("paper-initial", "paper-optimized", ...) from assets/layouts, or a path.
Layout load_layout_or_preset(const std::string& name_or_path);

}  // namespace lmc
