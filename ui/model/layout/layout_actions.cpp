#include "ui/model/layout/layout_actions.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "core/io/sensor_catalogue_json.h"

namespace lmc::ui {
namespace {

bool valid_index(const UndoableLayoutDocument& doc, int index) {
  return index >= 0 && index < doc.scratch().device_count();
}

std::string slot_of(const UndoableLayoutDocument& doc, int index) {
  return doc.scratch().layout.devices[static_cast<size_t>(index)].slot;
}

ActionResult bad_index(int index) {
  return ActionResult::fail("no controller #" + std::to_string(index + 1));
}

// Runs validate_layout on scratch; on failure rolls back and reports.
ActionResult commit_checked(UndoableLayoutDocument& doc, const std::string& message) {
  if (std::string why = validate_layout(doc.scratch().layout); !why.empty()) {
    doc.rollback();
    return ActionResult::fail(why);
  }
  doc.commit(message);
  return ActionResult::success();
}

bool finite_pose(const DevicePose& p) {
  for (int k = 0; k < kNumPoseParams; ++k) {
    if (!std::isfinite(p.get(k))) return false;
  }
  return true;
}

}  // namespace

ActionResult add_device(UndoableLayoutDocument& doc) {
  doc.rollback();
  LayoutDocument& d = doc.upd_scratch();
  if (d.device_count() >= kMaxDevices) {
    doc.rollback();
    return ActionResult::fail("a layout holds at most " + std::to_string(kMaxDevices) + " controllers");
  }
  std::string slot;
  for (int n = 1; n <= kMaxDevices + 1; ++n) {
    slot = "LMC" + std::to_string(n);
    if (d.layout.find_slot(slot) < 0) break;
  }
  LayoutDevice dev;
  dev.slot = slot;
  // Beside the right-most controller, so the new one is visible and not inside another.
  double max_x = -150.0;
  for (const auto& other : d.layout.devices) max_x = std::max(max_x, other.pose.x_mm);
  dev.pose.x_mm = max_x + 120.0;
  d.layout.devices.push_back(dev);
  d.sync_locks();
  return commit_checked(doc, "Add " + slot);
}

ActionResult remove_device(UndoableLayoutDocument& doc, int index) {
  doc.rollback();
  if (!valid_index(doc, index)) return bad_index(index);
  if (doc.scratch().device_count() <= 1) return ActionResult::fail("a layout needs at least one controller");
  const std::string slot = slot_of(doc, index);
  LayoutDocument& d = doc.upd_scratch();
  d.layout.devices.erase(d.layout.devices.begin() + index);
  d.locks.erase(d.locks.begin() + index);
  return commit_checked(doc, "Remove " + slot);
}

ActionResult rename_slot(UndoableLayoutDocument& doc, int index, const std::string& slot) {
  doc.rollback();
  if (!valid_index(doc, index)) return bad_index(index);
  if (slot.empty()) return ActionResult::fail("a slot name cannot be empty");
  const std::string old = slot_of(doc, index);
  if (old == slot) return ActionResult::success();
  const int clash = doc.scratch().layout.find_slot(slot);
  if (clash >= 0 && clash != index) return ActionResult::fail("slot name '" + slot + "' is already used");
  doc.upd_scratch().layout.devices[static_cast<size_t>(index)].slot = slot;
  return commit_checked(doc, "Rename " + old + " to " + slot);
}

ActionResult assign_serial(UndoableLayoutDocument& doc, int index, const std::string& serial) {
  doc.rollback();
  if (!valid_index(doc, index)) return bad_index(index);
  const std::string slot = slot_of(doc, index);
  auto& dev = doc.upd_scratch().layout.devices[static_cast<size_t>(index)];
  if (serial.empty()) {
    dev.serial.reset();
    return commit_checked(doc, "Clear serial of " + slot);
  }
  const int clash = doc.scratch().layout.find_serial(serial);
  if (clash >= 0 && clash != index) {
    doc.rollback();
    return ActionResult::fail("serial '" + serial + "' is already bound to " + slot_of(doc, clash));
  }
  dev.serial = serial;
  return commit_checked(doc, "Assign serial " + serial + " to " + slot);
}

ActionResult set_pose_param(UndoableLayoutDocument& doc, int index, int k, double value) {
  doc.rollback();
  if (!valid_index(doc, index)) return bad_index(index);
  if (k < 0 || k >= kNumPoseParams) return ActionResult::fail("no pose parameter #" + std::to_string(k));
  if (!std::isfinite(value)) return ActionResult::fail(std::string(pose_param_name(k)) + " must be a finite number");
  const std::string slot = slot_of(doc, index);
  doc.upd_scratch().layout.devices[static_cast<size_t>(index)].pose.set(k, value);
  return commit_checked(doc, "Set " + slot + " " + pose_param_name(k));
}

ActionResult set_device_pose(UndoableLayoutDocument& doc, int index, const DevicePose& pose) {
  if (ActionResult r = preview_device_pose(doc, index, pose); !r) return r;
  commit_device_pose(doc, index, "Move");
  return ActionResult::success();
}

ActionResult preview_device_pose(UndoableLayoutDocument& doc, int index, const DevicePose& pose) {
  if (!valid_index(doc, index)) return bad_index(index);
  if (!finite_pose(pose)) return ActionResult::fail("the pose is not finite");
  doc.upd_scratch().layout.devices[static_cast<size_t>(index)].pose = pose;
  return ActionResult::success();
}

bool commit_device_pose(UndoableLayoutDocument& doc, int index, const std::string& verb) {
  if (!valid_index(doc, index)) {
    doc.rollback();
    return false;
  }
  return doc.commit(verb + " " + slot_of(doc, index));
}

void cancel_preview(UndoableLayoutDocument& doc) {
  doc.rollback();
}

ActionResult set_device_lock(UndoableLayoutDocument& doc, int index, int k, bool locked) {
  doc.rollback();
  if (!valid_index(doc, index)) return bad_index(index);
  if (k < 0 || k >= kNumPoseParams) return ActionResult::fail("no pose parameter #" + std::to_string(k));
  doc.upd_scratch().sync_locks();
  doc.upd_scratch().locks[static_cast<size_t>(index)].locked[static_cast<size_t>(k)] = locked;
  doc.commit(std::string(locked ? "Lock " : "Unlock ") + slot_of(doc, index) + " " + pose_param_name(k));
  return ActionResult::success();
}

ActionResult set_device_movable(UndoableLayoutDocument& doc, int index, bool movable) {
  doc.rollback();
  if (!valid_index(doc, index)) return bad_index(index);
  doc.upd_scratch().sync_locks();
  DeviceLocks& l = doc.upd_scratch().locks[static_cast<size_t>(index)];
  for (int k = 0; k < kNumPoseParams; ++k) l.locked[static_cast<size_t>(k)] = movable ? (k == 1 || k == 5) : true;
  doc.commit(slot_of(doc, index) + (movable ? " may move" : " stays put"));
  return ActionResult::success();
}

ActionResult set_search_range(UndoableLayoutDocument& doc, int k, double lo, double hi) {
  doc.rollback();
  if (k < 0 || k >= kNumPoseParams) return ActionResult::fail("no pose parameter #" + std::to_string(k));
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
    return ActionResult::fail(std::string("bounds for ") + pose_param_name(k) + " need finite lo <= hi");
  }
  doc.upd_scratch().bounds.range[static_cast<size_t>(k)] = ParamRange{lo, hi};
  doc.commit(std::string("Set search bounds of ") + pose_param_name(k));
  return ActionResult::success();
}

ActionResult set_pose_set_choice(UndoableLayoutDocument& doc, const PoseSetChoice& choice) {
  doc.rollback();
  if (choice.source == PoseSetChoice::Source::kMonteCarlo && (choice.frames < 1 || choice.frames > 1000000)) {
    return ActionResult::fail("a Monte Carlo pose set needs 1 to 1,000,000 frames");
  }
  if (choice.source == PoseSetChoice::Source::kFile && choice.file.empty()) {
    return ActionResult::fail("choose a pose-set file");
  }
  if (choice.source == PoseSetChoice::Source::kRecordings) {
    if (choice.recordings.empty()) return ActionResult::fail("choose recorded trials or a session");
    if (choice.every < 1) return ActionResult::fail("keep every frame (1) or every N-th (N > 1)");
  }
  doc.upd_scratch().pose_set = choice;
  doc.commit("Change pose set");
  return ActionResult::success();
}

namespace {

// The undo label of a sensor edit: the one thing that changed, or "Sensor" for several.
std::string sensor_change_name(const SensorModel& before, const SensorModel& after) {
  std::vector<std::string> changed;
  if (before.range_mm != after.range_mm) changed.emplace_back("Range");
  if (before.range_near_mm != after.range_near_mm) changed.emplace_back("Near range");
  if (before.fov_long_deg != after.fov_long_deg || before.fov_short_deg != after.fov_short_deg)
    changed.emplace_back("Field of view");
  if (before.axis_cut_mm != after.axis_cut_mm) changed.emplace_back("Axis cut");
  return changed.size() == 1 ? changed.front() : "Sensor";
}

const SensorSpec* catalogue_model(const std::string& model_id) {
  return sensor_catalogue().find(model_id);
}

ActionResult unknown_model_error(const std::string& model_id) {
  return ActionResult::fail("unknown sensor model '" + model_id + "' (known: " + sensor_catalogue().known_ids() + ")");
}

}  // namespace

ActionResult set_device_model(UndoableLayoutDocument& doc, int index, const std::string& model_id) {
  doc.rollback();
  if (!valid_index(doc, index)) return bad_index(index);
  const SensorSpec* spec = catalogue_model(model_id);
  if (!spec) return unknown_model_error(model_id);
  LayoutDevice& dev = doc.upd_scratch().layout.devices[static_cast<size_t>(index)];
  const LayoutDevice was = dev;
  lmc::set_device_model(dev, *spec);
  if (dev == was) {
    doc.rollback();
    return ActionResult::success();
  }
  return commit_checked(doc, "Model of " + slot_of(doc, index) + ": " + spec->name);
}

ActionResult set_every_device_model(UndoableLayoutDocument& doc, const std::string& model_id) {
  doc.rollback();
  const SensorSpec* spec = catalogue_model(model_id);
  if (!spec) return unknown_model_error(model_id);
  const Layout was = doc.scratch().layout;
  set_all_models(doc.upd_scratch().layout, *spec);
  if (doc.scratch().layout == was) {
    doc.rollback();
    return ActionResult::success();
  }
  return commit_checked(doc, "Model of every controller: " + spec->name);
}

ActionResult preview_device_sensor(UndoableLayoutDocument& doc, int index, const SensorModel& sensor) {
  if (!valid_index(doc, index)) return bad_index(index);
  doc.upd_scratch().layout.devices[static_cast<size_t>(index)].sensor = sensor;
  return ActionResult::success();
}

ActionResult set_device_sensor(UndoableLayoutDocument& doc, int index, const SensorModel& sensor) {
  doc.rollback();
  if (!valid_index(doc, index)) return bad_index(index);
  SensorModel& current = doc.upd_scratch().layout.devices[static_cast<size_t>(index)].sensor;
  const SensorModel before = current;
  if (before == sensor) {
    doc.rollback();
    return ActionResult::success();
  }
  current = sensor;
  return commit_checked(doc, sensor_change_name(before, sensor) + " of " + slot_of(doc, index));
}

ActionResult reset_device_sensor(UndoableLayoutDocument& doc, int index) {
  doc.rollback();
  if (!valid_index(doc, index)) return bad_index(index);
  const LayoutDevice& dev = doc.scratch().layout.devices[static_cast<size_t>(index)];
  const SensorSpec* spec = catalogue_model(dev.model);
  if (!spec) return unknown_model_error(dev.model);
  if (dev.sensor == spec->sensor) return ActionResult::success();
  doc.upd_scratch().layout.devices[static_cast<size_t>(index)].sensor = spec->sensor;
  return commit_checked(doc, "Reset " + slot_of(doc, index) + " to its model");
}

ActionResult replace_layout(UndoableLayoutDocument& doc, const Layout& layout, const std::string& what) {
  doc.rollback();
  if (std::string why = validate_layout(layout); !why.empty()) return ActionResult::fail(why);
  LayoutDocument& d = doc.upd_scratch();
  // Keep the user's locks for slots that exist in both layouts.
  std::map<std::string, DeviceLocks> old_locks;
  for (size_t i = 0; i < d.layout.devices.size() && i < d.locks.size(); ++i) {
    old_locks[d.layout.devices[i].slot] = d.locks[i];
  }
  d.layout = layout;
  d.locks.assign(layout.devices.size(), DeviceLocks{});
  for (size_t i = 0; i < layout.devices.size(); ++i) {
    if (auto it = old_locks.find(layout.devices[i].slot); it != old_locks.end()) d.locks[i] = it->second;
  }
  doc.commit(what);
  return ActionResult::success();
}

namespace {

// What apply_layout and apply_calibration share: copy each matching slot's placement from `source`
// into the document (the offset too when `with_offsets`), refusing non-finite values and a source
// that shares no slot. `noun` names the source in messages ("optimised", "calibrated"). Leaves the
// scratch open for the caller to finish and commit.
ActionResult copy_placements_by_slot(UndoableLayoutDocument& doc, const Layout& source, bool with_offsets,
                                     const std::string& noun) {
  doc.rollback();
  LayoutDocument& d = doc.upd_scratch();
  int matched = 0;
  for (auto& dev : d.layout.devices) {
    const int j = source.find_slot(dev.slot);
    if (j < 0) continue;
    const LayoutDevice& c = source.devices[static_cast<size_t>(j)];
    if (!finite_pose(c.pose) || (with_offsets && !c.offset_mm.allFinite())) {
      doc.rollback();
      return ActionResult::fail("the " + noun + " pose of " + dev.slot + " is not finite");
    }
    dev.pose = c.pose;
    if (with_offsets) dev.offset_mm = c.offset_mm;
    ++matched;
  }
  if (matched == 0) {
    doc.rollback();
    return ActionResult::fail("the " + noun + " layout shares no slot with the current one");
  }
  return ActionResult::success();
}

}  // namespace

ActionResult apply_layout(UndoableLayoutDocument& doc, const Layout& optimised) {
  if (ActionResult r = copy_placements_by_slot(doc, optimised, false, "optimised"); !r.ok) return r;
  // A searched layout carries what made it (the optimiser job names it); keep the old name and
  // description only when the candidate has none.
  LayoutDocument& d = doc.upd_scratch();
  if (!optimised.name.empty()) d.layout.name = optimised.name;
  if (!optimised.description.empty()) d.layout.description = optimised.description;
  return commit_checked(doc, "Apply optimised layout");
}

ActionResult apply_calibration(UndoableLayoutDocument& doc, const Layout& calibrated) {
  if (ActionResult r = copy_placements_by_slot(doc, calibrated, true, "calibrated"); !r.ok) return r;
  LayoutDocument& d = doc.upd_scratch();
  d.layout.name = calibrated.name;
  d.layout.description = calibrated.description;
  return commit_checked(doc, "Apply calibration");
}

Layout default_new_layout() {
  return square_layout("untitled");
}

}  // namespace lmc::ui
