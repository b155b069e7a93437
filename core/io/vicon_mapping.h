#pragma once
// Vicon marker set → the controller's 30-point layout (docs/algorithms/vicon.md), as data:
// `assets/mappings/vicon-26-to-lmc.json` (format 1) lists the marker names it expects and, for each
// target point by its study name ("Palm Position", "Finger3_Meta", …), a weighted sum of markers.
// Targets it leaves out (palm normal and direction) are zero, as in the study. A lab with another
// marker set edits the file, not the code.
#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/hand/hand_track.h"

namespace lmc {

struct ViconMapping {
  std::string name;
  std::vector<std::string> markers;  // every marker the mapping uses
  // terms[point] = (marker index into `markers`, weight); empty → the point is zero.
  std::vector<std::vector<std::pair<int, double>>> terms =
      std::vector<std::vector<std::pair<int, double>>>(kNumHandPoints);
};

ViconMapping vicon_mapping_from_json(const nlohmann::json& j, const std::string& source);
ViconMapping load_vicon_mapping(const std::filesystem::path& path);
// The shipped default (assets/mappings/vicon-26-to-lmc.json).
ViconMapping default_vicon_mapping();

// Marker trajectories from any reader (TRC, C3D): names and positions[frame][marker] in mm.
struct MarkerSeries {
  std::vector<std::string> names;
  std::vector<std::vector<Eigen::Vector3d>> positions;
  double rate_hz = 100.0;
  std::string source;  // file, for messages
};

// Applies the mapping. A marker the mapping needs that is absent from the file, or NaN in every
// frame, is an lmc::Error naming the file and the marker. Names match exactly first, then with a
// "Subject:" prefix removed (C3D labels often carry one). NaN in a frame gives NaN for the points
// that use that marker in that frame.
HandTrack apply_vicon_mapping(const ViconMapping& mapping, const MarkerSeries& markers);

}  // namespace lmc
