#pragma once
// Everything a user can do to a layout document, as named actions (docs/architecture.md). Each action
// validates its input, edits the scratch copy and commits with a message naming the device, so
// every edit is one undo step with a readable label ("Move LMC2"). A rejected action returns
// its reason and leaves no commit (and no scratch edits).
//
// UI-only steps (file dialogs, confirmations) live in the tab; they call these afterwards.
#include <optional>
#include <string>

#include "core/layout/layout.h"
#include "ui/model/layout/layout_document.h"
#include "ui/model/layout/undo_redo.h"

namespace lmc::ui {

using UndoableLayoutDocument = UndoRedo<LayoutDocument>;

struct ActionResult {
  bool ok = true;
  std::string error;  // why it was rejected; empty when ok
  explicit operator bool() const { return ok; }
  static ActionResult success() { return {}; }
  static ActionResult fail(std::string why) { return {false, std::move(why)}; }
};

// ---- devices ------------------------------------------------------------------------------
// Adds a controller with the next free slot name ("LMC5"), placed beside the others. Max 8.
ActionResult add_device(UndoableLayoutDocument& doc);
// Removes device `index`. At least one controller must remain.
ActionResult remove_device(UndoableLayoutDocument& doc, int index);
// Renames a slot; the name must be non-empty and unique.
ActionResult rename_slot(UndoableLayoutDocument& doc, int index, const std::string& slot);
// Binds a serial number to a slot (empty string clears it); serials must be unique.
ActionResult assign_serial(UndoableLayoutDocument& doc, int index, const std::string& serial);

// ---- poses --------------------------------------------------------------------------------
// Sets one pose parameter (k in {x, y, z, rx, ry, rz} order) and commits.
ActionResult set_pose_param(UndoableLayoutDocument& doc, int index, int k, double value);
// Sets a whole pose and commits ("Move LMC1", used by the inspector and tests).
ActionResult set_device_pose(UndoableLayoutDocument& doc, int index, const DevicePose& pose);
// Drag/slider pairing: write the pose into scratch every frame without a commit ...
ActionResult preview_device_pose(UndoableLayoutDocument& doc, int index, const DevicePose& pose);
// ... then commit once on release (one undo step per drag). `verb` names the gesture
// ("Move", "Rotate", "Tilt"). Returns false when nothing changed (no commit).
bool commit_device_pose(UndoableLayoutDocument& doc, int index, const std::string& verb);
// Escape during a drag: throw the scratch edits away.
void cancel_preview(UndoableLayoutDocument& doc);

// ---- locks, bounds, pose set -------------------------------------------------------------------
ActionResult set_device_lock(UndoableLayoutDocument& doc, int index, int k, bool locked);
// All six locks of one device in one step: `movable` frees the study's {x, z, rx, ry} (y and rz
// stay locked), otherwise everything is locked ("LMC2 may move" / "LMC2 stays put").
ActionResult set_device_movable(UndoableLayoutDocument& doc, int index, bool movable);
ActionResult set_search_range(UndoableLayoutDocument& doc, int k, double lo, double hi);
ActionResult set_pose_set_choice(UndoableLayoutDocument& doc, const PoseSetChoice& choice);

// ---- each controller's model and sensor ----------------------------------------------------------
// One controller becomes a catalogue model (sensor_catalogue()), its overrides dropped and its case
// the model's: "Model of LMC3: Leap Motion Controller 2". Picking the model it already is, without
// overrides, changes nothing and adds no undo step.
ActionResult set_device_model(UndoableLayoutDocument& doc, int index, const std::string& model_id);
// Every controller becomes that model, in one undo step ("Model of every controller: …").
ActionResult set_every_device_model(UndoableLayoutDocument& doc, const std::string& model_id);
// A drag on one of a controller's sensor fields: the values go into the scratch copy every frame
// without a commit, so the pyramid follows live ...
ActionResult preview_device_sensor(UndoableLayoutDocument& doc, int index, const SensorModel& sensor);
// ... and one commit on release: one controller's sensor values, which become overrides of its
// model where they differ from the catalogue's. The undo step names what changed ("Range of
// LMC3", "Near range of LMC3", "Field of view of LMC3", "Axis cut of LMC3", "Sensor of LMC3" for
// several at once); no change adds no step.
ActionResult set_device_sensor(UndoableLayoutDocument& doc, int index, const SensorModel& sensor);
// Drops a controller's overrides: its sensor becomes its model's again ("Reset LMC3 to its model").
ActionResult reset_device_sensor(UndoableLayoutDocument& doc, int index);

// ---- whole layouts ----------------------------------------------------------------------------
// Replaces the layout (keeps locks where slots survive). `what` names it in the undo label:
// "Load preset paper-optimized", "Open my-rig.json", "New layout".
ActionResult replace_layout(UndoableLayoutDocument& doc, const Layout& layout, const std::string& what);
// Applies an optimised layout: poses only, matched by slot; one undo step ("Apply optimised layout").
ActionResult apply_layout(UndoableLayoutDocument& doc, const Layout& optimised);

// Applies a calibrated layout (core/calibration/calibrated_layout.h): every matched slot's pose
// and offset, and the name and description that say where the calibration came from; one undo
// step ("Apply calibration").
ActionResult apply_calibration(UndoableLayoutDocument& doc, const Layout& calibrated);

// The layout a "New" command starts from: four controllers in the paper's initial square
// (docs/algorithms/frames.md, ±60 mm), no serials.
Layout default_new_layout();

}  // namespace lmc::ui
