#pragma once
// One processed trial's files for one BIDS-motion tracking system, as text (bids_dataset.cpp writes
// them). The channels come from the trial's point table (trial_points.h), split by label prefix:
// F_ the fused hand, LMC<n>_ controller n, V_ the Vicon markers. Each tracked point gives three
// channels <point>_x, _y, _z of type POS in mm, in the world frame (x along the table = the
// subject's right, y up, z towards the subject), at the processing grid's rate.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/export/trial_points.h"

namespace lmc {

struct BidsTrackingSystem {
  std::string name;                         // the tracksys label: LMCfused, LMC1…, Vicon
  int device_id = 0;                        // controllers only
  std::vector<int> columns;                 // the table's points, in file order
  std::vector<std::string> tracked_points;  // their labels without the prefix ("Palm", "RFIN")
};

// In table order: the fused hand, each controller, Vicon (when the table has it).
std::vector<BidsTrackingSystem> bids_tracking_systems(const PointTable& table);

// What BIDS-motion calls a missing value in the data and its sidecar.
inline constexpr const char* kBidsMissingValue = "n/a";

// *_motion.tsv: no header (BIDS-motion), one row per frame, x y z per tracked point, mm with three
// decimals, kBidsMissingValue where the point has no data.
std::string bids_motion_tsv(const PointTable& table, const BidsTrackingSystem& system);
// *_channels.tsv: name, component, type, tracked_point, units, reference_frame, description.
std::string bids_channels_tsv(const PointTable& table, const BidsTrackingSystem& system);
// *_channels.json: the one reference frame the channels name.
nlohmann::json bids_channels_json();

struct BidsMotionInfo {
  std::string task_name;
  std::string task_description;
  std::string instructions;
  std::string tracking_system_name;
  std::string manufacturer;
  std::string model;   // empty: not known (left out)
  std::string serial;  // empty: not known (left out)
  std::string software_versions;
};

// *_motion.json: the keys BIDS-motion defines and no others (the validator allows no others).
nlohmann::json bids_motion_json(const PointTable& table, const BidsTrackingSystem& system, const BidsMotionInfo& info);

struct BidsEvent {
  double onset_s = 0;  // from the first row of the trial's motion files; may be negative
  double duration_s = 0;
  std::string type;  // go | stop | vicon_capture_start
};

// *_events.tsv: onset, duration, trial_type; seconds with three decimals.
std::string bids_events_tsv(const std::vector<BidsEvent>& events);

}  // namespace lmc
