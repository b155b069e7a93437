#include "core/io/vicon_mapping.h"

#include <cmath>

#include "core/common/error.h"
#include "core/common/paths.h"
#include "core/io/json_checked.h"

namespace lmc {

ViconMapping vicon_mapping_from_json(const nlohmann::json& j, const std::string& source) {
  JsonReader root(j, source);
  root.require_object();
  if (root.has("format") && root.at("format").integer() != 1)
    root.at("format").fail("unsupported mapping format (expected 1)");
  ViconMapping m;
  m.name = root.string_or("name", "");
  const JsonReader markers = root.at("markers");
  for (size_t k = 0; k < markers.array_size(); ++k) m.markers.push_back(markers.at(k).string());
  const JsonReader points = root.at("points");
  points.require_object();
  for (const auto& [key, value] : points.json().items()) {
    const auto idx = hand_point_from_name(key);
    const JsonReader entry = points.at(key.c_str());
    if (!idx) entry.fail("unknown point name '" + key + "' (expected a study name such as \"Finger2_Proxi\")");
    entry.require_object();
    for (const auto& [marker, weight] : value.items()) {
      int mi = -1;
      for (size_t k = 0; k < m.markers.size(); ++k) {
        if (m.markers[k] == marker) mi = static_cast<int>(k);
      }
      const JsonReader w = entry.at(marker.c_str());
      if (mi < 0) w.fail("marker '" + marker + "' is not in the \"markers\" list");
      m.terms[static_cast<size_t>(*idx)].emplace_back(mi, w.number());
    }
  }
  return m;
}

ViconMapping load_vicon_mapping(const std::filesystem::path& path) {
  return vicon_mapping_from_json(read_json_file(path), path.string());
}

ViconMapping default_vicon_mapping() {
  return load_vicon_mapping(asset_path("mappings/vicon-26-to-lmc.json"));
}

namespace {

int find_marker(const std::vector<std::string>& names, const std::string& wanted) {
  for (size_t k = 0; k < names.size(); ++k) {
    if (names[k] == wanted) return static_cast<int>(k);
  }
  for (size_t k = 0; k < names.size(); ++k) {
    const auto colon = names[k].rfind(':');
    if (colon != std::string::npos && names[k].substr(colon + 1) == wanted) return static_cast<int>(k);
  }
  return -1;
}

}  // namespace

HandTrack apply_vicon_mapping(const ViconMapping& mapping, const MarkerSeries& markers) {
  const int frames = static_cast<int>(markers.positions.size());
  // Resolve only markers that some point uses.
  std::vector<int> column(mapping.markers.size(), -1);
  std::vector<bool> used(mapping.markers.size(), false);
  for (const auto& t : mapping.terms) {
    for (const auto& [mi, w] : t) used[static_cast<size_t>(mi)] = true;
  }
  for (size_t k = 0; k < mapping.markers.size(); ++k) {
    if (!used[k]) continue;
    const int c = find_marker(markers.names, mapping.markers[k]);
    if (c < 0) {
      throw Error(ErrorLocation(markers.source),
                  "marker '" + mapping.markers[k] + "' needed by mapping '" + mapping.name + "' is not in the file");
    }
    bool any = false;
    for (int f = 0; f < frames && !any; ++f)
      any = is_finite(markers.positions[static_cast<size_t>(f)][static_cast<size_t>(c)]);
    if (!any) {
      throw Error(ErrorLocation(markers.source), "marker '" + mapping.markers[k] + "' is missing in every frame (" +
                                                     std::to_string(frames) + " frames)");
    }
    column[k] = c;
  }
  HandTrack track(frames);
  for (int f = 0; f < frames; ++f) {
    const auto& row = markers.positions[static_cast<size_t>(f)];
    for (int i = 0; i < kNumHandPoints; ++i) {
      const auto& t = mapping.terms[static_cast<size_t>(i)];
      Vec3 p = Vec3::Zero();
      for (const auto& [mi, w] : t) p += w * row[static_cast<size_t>(column[static_cast<size_t>(mi)])];
      track.at(f, i) = p;
    }
  }
  return track;
}

}  // namespace lmc
