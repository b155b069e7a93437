#pragma once
// The list of controllers (select, add, remove) and every parameter of the selected one: slot
// name, serial number, pose x, y, z, rx, ry, rz with a lock each (locks are document state: the
// optimiser and the scene handles leave locked parameters alone), the calibration offset, and the
// controller's own model (a catalogue entry, assets/sensors/sensors.json) with its sensor values,
// each marked where it overrides the model. Slider edits preview live and commit once on release
// (one undo step); a single click without dragging types a value into a pose field.
#include <memory>
#include <string>

#include "core/layout/sensor_catalogue.h"
#include "ui/model/layout/layout_state.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class InspectorPanel : public Panel {
 public:
  explicit InspectorPanel(std::shared_ptr<LayoutState> state) : Panel("##inspector_body"), state_(std::move(state)) {}
  void draw();
  // "add", "remove", "device.<i>", "lock.<k>", "pose.<k>", "model", "model.<id>" (while the combo
  // is open), "sensor.<field>", "override.<field>" (only when overridden), "reset-sensor",
  // "model-to-all" as last drawn (for headless tests).
  const WidgetAnchors& anchors() const { return anchors_; }
  // Scrolls the panel to the selected controller's model on the next draw (the mixed-rig capture).
  void show_model_once() { scroll_to_model_ = true; }

 private:
  void draw_device(int index);
  // The selected controller's catalogue model, its sensor values (marked where they override the
  // model's), "Reset to model" and "Apply this model to all controllers".
  void draw_model_and_sensor(int index);
  void draw_model_combo(int index);
  void draw_sensor_fields(int index);
  void draw_position_noise(const SensorSpec& spec);
  void draw_model_buttons(int index);

  std::shared_ptr<LayoutState> state_;
  WidgetAnchors anchors_;
  char slot_buf_[64] = {};
  char serial_buf_[64] = {};
  int buffers_for_ = -2;
  std::uint64_t buffers_head_ = 0;
  // A click on a pose field that did not drag it opens it for typing on the next frame (ImGui
  // 1.86 only types into a drag field on double-click or Ctrl+click, which nobody guesses).
  int type_into_pose_ = -1;
  bool scroll_to_model_ = false;
};

}  // namespace lmc::ui
