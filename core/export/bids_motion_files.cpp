#include "core/export/bids_motion_files.h"

#include <cmath>

#include "core/common/number_format.h"
#include "core/export/bids_names.h"

namespace lmc {
namespace bids_motion_detail {  // named: core compiles in unity batches

// The system a label belongs to and the tracked point's name, from the point table's prefixes.
bool split_label(const std::string& label, std::string* system, int* device_id, std::string* point) {
  if (label.rfind("F_", 0) == 0) {
    *system = kBidsFusedTracksys;
    *point = label.substr(2);
    return true;
  }
  if (label.rfind("V_", 0) == 0) {
    *system = kBidsViconTracksys;
    *point = label.substr(2);
    return true;
  }
  if (label.rfind("LMC", 0) == 0) {
    const size_t underscore = label.find('_', 3);
    if (underscore == std::string::npos || underscore == 3) return false;
    const std::string digits = label.substr(3, underscore - 3);
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 3) return false;
    *device_id = std::stoi(digits);
    *system = bids_device_tracksys(*device_id);
    *point = label.substr(underscore + 1);
    return true;
  }
  return false;
}

std::string coordinate(double v) {
  return std::isfinite(v) ? format_fixed(v, 3) : std::string(kBidsMissingValue);
}

}  // namespace bids_motion_detail

std::vector<BidsTrackingSystem> bids_tracking_systems(const PointTable& table) {
  std::vector<BidsTrackingSystem> systems;
  for (int i = 0; i < table.point_count(); ++i) {
    std::string system, point;
    int device_id = 0;
    if (!bids_motion_detail::split_label(table.labels[static_cast<size_t>(i)], &system, &device_id, &point)) continue;
    if (systems.empty() || systems.back().name != system) systems.push_back({system, device_id, {}, {}});
    systems.back().columns.push_back(i);
    systems.back().tracked_points.push_back(point);
  }
  return systems;
}

std::string bids_motion_tsv(const PointTable& table, const BidsTrackingSystem& system) {
  std::string out;
  for (const auto& row : table.positions) {
    bool first = true;
    for (const int c : system.columns) {
      const Eigen::Vector3d& p = row[static_cast<size_t>(c)];
      for (int k = 0; k < 3; ++k) {
        if (!first) out += '\t';
        out += bids_motion_detail::coordinate(p[k]);
        first = false;
      }
    }
    out += '\n';
  }
  return out;
}

std::string bids_channels_tsv(const PointTable& table, const BidsTrackingSystem& system) {
  std::string out = "name\tcomponent\ttype\ttracked_point\tunits\treference_frame\tdescription\n";
  for (size_t i = 0; i < system.columns.size(); ++i) {
    const std::string& point = system.tracked_points[i];
    const std::string& description = table.descriptions[static_cast<size_t>(system.columns[i])];
    for (const char* axis : {"x", "y", "z"}) {
      out += point + "_" + axis + "\t" + axis + "\tPOS\t" + point + "\tmm\tworld\t" + description + "\n";
    }
  }
  return out;
}

nlohmann::json bids_channels_json() {
  // The rig's world frame seen from the subject: x to the right (R), y up (S), z towards the
  // subject (P). A right-handed frame; positions only, so no rotation order applies.
  return {{"reference_frame",
           {{"Description", "The reference frame of the positions"},
            {"Levels",
             {{"world",
               {{"Description",
                 "The rig's world frame (docs/algorithms/frames.md): x along the table to the subject's right, "
                 "y up (table top y = 0), z towards the subject; origin at the centre of the controllers' layout"},
                {"SpatialAxes", "RSP"},
                {"RotationRule", "right-hand"}}}}}}}};
}

nlohmann::json bids_motion_json(const PointTable& table, const BidsTrackingSystem& system, const BidsMotionInfo& info) {
  nlohmann::json j;
  j["TaskName"] = info.task_name;
  if (!info.task_description.empty()) j["TaskDescription"] = info.task_description;
  if (!info.instructions.empty()) j["Instructions"] = info.instructions;
  j["RecordingType"] = "continuous";
  j["SamplingFrequency"] = table.rate_hz;
  j["RecordingDuration"] = table.frame_count() / table.rate_hz;
  j["TrackingSystemName"] = info.tracking_system_name;
  j["Manufacturer"] = info.manufacturer;
  if (!info.model.empty()) j["ManufacturersModelName"] = info.model;
  if (!info.serial.empty()) j["DeviceSerialNumber"] = info.serial;
  j["SoftwareVersions"] = info.software_versions;
  j["TrackedPointsCount"] = static_cast<int>(system.columns.size());
  j["POSChannelCount"] = static_cast<int>(3 * system.columns.size());
  j["MotionChannelCount"] = static_cast<int>(3 * system.columns.size());
  j["MissingValues"] = kBidsMissingValue;
  return j;
}

std::string bids_events_tsv(const std::vector<BidsEvent>& events) {
  std::string out = "onset\tduration\ttrial_type\n";
  for (const auto& e : events)
    out += format_fixed(e.onset_s, 3) + "\t" + format_fixed(e.duration_s, 3) + "\t" + e.type + "\n";
  return out;
}

}  // namespace lmc
