#pragma once
// A *layout* is where the lab's controllers stand: a named list of devices, each with a slot name
// (LMC1…), an optional serial number that binds a physical controller to the slot, a pose and the
// per-device offset measured at calibration (applied after the pose, docs/algorithms/frames.md),
// plus the sensor model they share. It is a plain value: copy it, compare it, undo it.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/layout/device_pose.h"
#include "core/layout/sensor_model.h"

namespace lmc {

inline constexpr int kMaxDevices = 8;

struct LayoutDevice {
  std::string slot;                   // "LMC1" …; unique within a layout
  std::optional<std::string> serial;  // unique when present
  DevicePose pose;
  Eigen::Vector3d offset_mm = Eigen::Vector3d::Zero();

  // Device frame → world frame, offset included: p = R·p_d + t + offset.
  Eigen::Vector3d to_world(const Eigen::Vector3d& p_device) const { return pose.to_world(p_device) + offset_mm; }

  bool operator==(const LayoutDevice&) const = default;
};

struct Layout {
  std::string name;
  std::string description;
  SensorModel sensor;
  std::vector<LayoutDevice> devices;

  int device_count() const { return static_cast<int>(devices.size()); }
  // Index of the device with this slot name, or −1.
  int find_slot(const std::string& slot) const;
  // Index of the device bound to this serial, or −1.
  int find_serial(const std::string& serial) const;

  bool operator==(const Layout&) const = default;
};

// Checks a layout's invariants (1–8 devices, unique non-empty slot names and serials, finite
// numbers, sane sensor model). Returns an empty string when fine, else the first problem with
// the JSON-style path of the offending field ("/devices/2/pose/rx: not a finite number").
std::string validate_layout(const Layout& layout);

// Four controllers flat on the table in the study's initial square, LMC1…LMC4 at (x, z) =
// (−60, 60), (60, 60), (−60, −60), (60, −60) mm, no offsets, no serials, the study's sensor: what a
// new layout starts from (the preset paper-initial adds the authors' measured offsets).
Layout square_layout(std::string name);

}  // namespace lmc
