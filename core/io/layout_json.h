#pragma once
// Layout files (assets/layouts/*.json, user layouts). Format version 1:
//   { "format": 1, "name": "...", "description": "...",
//     "sensor": { "range_mm": 600, "fov_long_deg": 150, "fov_short_deg": 120 },
//     "devices": [ { "slot": "LMC1", "serial": "LP12345" | null,
//                    "pose": { "x": 0, "y": 0, "z": 0, "rx": 0, "ry": 0, "rz": 0 },
//                    "offset": [0, 0, 0] }, ... ] }
// Pose in mm and degrees (docs/algorithms/frames.md); offset in mm, applied after the pose.
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "core/layout/layout.h"

namespace lmc {

inline constexpr int kLayoutFormatVersion = 1;

// Parses and validates; throws lmc::Error naming `source` and the JSON path of the problem.
Layout layout_from_json(const nlohmann::json& j, const std::string& source);
nlohmann::json layout_to_json(const Layout& layout);

Layout load_layout(const std::filesystem::path& path);
// Atomic (temporary file + rename). Throws lmc::Error when the layout is invalid or the write fails.
void save_layout(const Layout& layout, const std::filesystem::path& path);

// A layout by preset name ("paper-initial", "paper-optimized", ...) from assets/layouts, or a path.
Layout load_layout_or_preset(const std::string& name_or_path);

}  // namespace lmc
