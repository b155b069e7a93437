#pragma once
// A *layout* is where the lab's controllers stand: a named list of devices, each with a slot name
// (LMC1…), an optional serial number that binds a physical controller to the slot, a pose and the
// per-device offset measured at calibration (applied after the pose, docs/algorithms/frames.md),
// and the controller model it is (a catalogue id, core/layout/sensor_catalogue.h) with what it sees:
// the model's SensorModel, or that with per-device overrides. It is a plain value: copy it, compare
// it, undo it.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/layout/device_pose.h"
#include "core/layout/sensor_catalogue.h"
#include "core/layout/sensor_model.h"

namespace lmc {

inline constexpr int kMaxDevices = 8;

struct LayoutDevice {
  std::string slot;                   // "LMC1" …; unique within a layout
  std::optional<std::string> serial;  // unique when present
  DevicePose pose;
  Eigen::Vector3d offset_mm = Eigen::Vector3d::Zero();
  // The catalogue model (SensorSpec::id) and what this device sees: the model's sensor, or that
  // with overrides (a layout file stores the fields in which it differs from the model's).
  std::string model = kStudySensorId;
  SensorModel sensor;
  // The model's case on the table (SensorSpec::footprint_mm): width along x, depth along z (mm).
  Eigen::Vector2d footprint_mm = Eigen::Vector2d(80.0, 30.0);

  // Device frame → world frame, offset included: p = R·p_d + t + offset.
  Eigen::Vector3d to_world(const Eigen::Vector3d& p_device) const { return pose.to_world(p_device) + offset_mm; }

  bool operator==(const LayoutDevice&) const = default;
};

struct Layout {
  std::string name;
  std::string description;
  std::vector<LayoutDevice> devices;

  int device_count() const { return static_cast<int>(devices.size()); }
  // Index of the device with this slot name, or −1.
  int find_slot(const std::string& slot) const;
  // Index of the device bound to this serial, or −1.
  int find_serial(const std::string& serial) const;

  bool operator==(const Layout&) const = default;
};

// Makes `device` a `spec` controller: its model id and the model's sensor (overrides dropped).
void set_device_model(LayoutDevice& device, const SensorSpec& spec);
// Every device a `spec` controller (what `lmc evaluate --models` and the all-one-model what-ifs do).
void set_all_models(Layout& layout, const SensorSpec& spec);
// The same sensor for every device (the study's assumption), keeping their model ids: what a
// global range or field-of-view setting does.
void set_all_sensors(Layout& layout, const SensorModel& sensor);
// What-if models per slot from a comma-separated list of catalogue ids ("lmc2,lmc2,lmc,lmc"): one
// id makes every device that model; otherwise one id per device, in layout order. Throws
// lmc::Error naming the list, the offending id and the known ids, or the count mismatch.
void set_models_from_list(Layout& layout, const std::string& ids, const SensorCatalogue& catalogue);

// True when every device sees through the same sensor model (the kernels' uniform case).
bool uniform_sensors(const Layout& layout);
// The sensor every device shares, for the paths that model one sensor for the whole rig; throws
// lmc::Error naming the first device that differs (and its model) when the rig is mixed.
const SensorModel& common_sensor(const Layout& layout);

// Checks a layout's invariants (1–8 devices, unique non-empty slot names and serials, finite
// numbers, a sane sensor model per device). Returns an empty string when fine, else the first problem with
// the JSON-style path of the offending field ("/devices/2/pose/rx: not a finite number").
std::string validate_layout(const Layout& layout);

// Four controllers flat on the table in the study's initial square, LMC1…LMC4 at (x, z) =
// (−60, 60), (60, 60), (−60, −60), (60, −60) mm, no offsets, no serials, the study's model: what a
// new layout starts from (the preset paper-initial adds the authors' measured offsets).
Layout square_layout(std::string name);

}  // namespace lmc
