#pragma once
// What the placement search may change (docs/algorithms/search.md): any subset of the six pose
// parameters {x, y, z, rx, ry, rz} (order of DevicePose::get), each with its own bounds, the same
// for every device; per-device locks keep a whole device, or single parameters of it, at the start
// layout's value (the workbench inspector's lock toggles).
#include <array>
#include <string>
#include <vector>

#include "core/layout/device_pose.h"
#include "core/layout/layout.h"

namespace lmc {

struct ParamBounds {
  double min = 0;
  double max = 0;
  bool operator==(const ParamBounds&) const = default;
};

struct SearchSpace {
  // Which parameters are searched (default: the paper's {x, z, rx, ry}).
  std::array<bool, kNumPoseParams> free{true, false, true, true, true, false};
  // Default: the authors' box, x, z ∈ [−1000, 1000] mm, rx ∈ [−90, 90]°, ry ∈ [−180, 180]°
  // (y and rz: [0, 0] unless freed).
  std::array<ParamBounds, kNumPoseParams> bounds{ParamBounds{-1000, 1000}, ParamBounds{0, 0},
                                                 ParamBounds{-1000, 1000}, ParamBounds{-90, 90},
                                                 ParamBounds{-180, 180},   ParamBounds{-180, 180}};
  // locked[d][k]: parameter k of device d stays at the start layout's value. Devices beyond the
  // vector's size are unlocked.
  std::vector<std::array<bool, kNumPoseParams>> locked;

  void lock_device(int device, bool on = true);
  void lock_param(int device, int param, bool on = true);
  bool is_locked(int device, int param) const;
  bool device_fully_locked(int device) const;

  // The searched coordinates for a layout of `devices` devices: (device, param) pairs, device
  // major, in parameter order. Its size is the PSO's dimension.
  std::vector<std::pair<int, int>> dimensions(int devices) const;

  // Empty when fine, else the first problem ("bounds for rx: min > max").
  std::string validate() const;
};

// Parses "x=-400:400,z=-400:400,rx=-45:45,ry=-180:180": sets those bounds and frees exactly the
// named parameters. Throws lmc::Error naming the offending item.
SearchSpace parse_search_bounds(const std::string& spec);
// The free parameters and their bounds in parse_search_bounds's form (what `lmc bench` prints);
// parse_search_bounds of it gives the same free parameters and bounds (locks are not written).
std::string format_search_bounds(const SearchSpace& space);

// The table top the workbench draws: x, z within ±400 mm of the set-up's centre.
inline constexpr double kTableHalfExtentMm = 400.0;
// The robust search's default: the paper's four parameters, with x and z keeping every
// controller whole on the table (centre within ±(400 − 40) mm), rx ∈ [−90, 90]°, ry ∈ [−180, 180]°.
SearchSpace table_search_space();

// A starting layout of `devices` devices (1–8) under the hand: in a row along x, 120 mm apart,
// at the table centre, all looking up, sensor model `sensor`; slots LMC1….
Layout default_start_layout(int devices, const SensorModel& sensor = {});

}  // namespace lmc
