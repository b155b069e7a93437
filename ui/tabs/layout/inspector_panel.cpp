#include "ui/tabs/layout/inspector_panel.h"

#include <imgui.h>

#include <cstdio>

#include "core/io/sensor_catalogue_json.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {

void InspectorPanel::draw() {
  anchors_.clear();
  LayoutState& s = *state_;
  const Layout& l = s.layout();
  ImGui::TextDisabled("Controllers (%d of 1-%d)", l.device_count(), kMaxDevices);
  ImGui::BeginChild("##devices", ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * std::min(l.device_count(), 5) + 8),
                    true);
  for (int i = 0; i < l.device_count(); ++i) {
    const LayoutDevice& d = l.devices[static_cast<size_t>(i)];
    char label[160];
    std::snprintf(label, sizeof label, "%-5s %-5s %-9s x %5.0f z %5.0f rx %5.1f ry %6.1f##dev%d", d.slot.c_str(),
                  d.model.c_str(), d.serial ? d.serial->c_str() : "", d.pose.x_mm, d.pose.z_mm, d.pose.rx_deg,
                  d.pose.ry_deg, i);
    if (ImGui::Selectable(label, s.selected() == i)) s.select(i);
    anchors_.remember("device." + std::to_string(i));
    if (ImGui::IsItemHovered()) {
      const SensorSpec* spec = sensor_catalogue().find(d.model);
      ImGui::SetTooltip("%s: %s", d.slot.c_str(), spec ? spec->name.c_str() : d.model.c_str());
    }
  }
  ImGui::EndChild();
  ImGui::BeginDisabled(l.device_count() >= kMaxDevices);
  if (ImGui::Button("Add controller")) {
    if (s.report(add_device(s.upd_history()), "Add controller")) s.select(s.doc().device_count() - 1);
  }
  anchors_.remember("add");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(s.selected() < 0 || l.device_count() <= 1);
  if (ImGui::Button("Remove selected")) s.report(remove_device(s.upd_history(), s.selected()), "Remove controller");
  anchors_.remember("remove");
  ImGui::EndDisabled();

  ImGui::Separator();
  if (s.selected() >= 0 && s.selected() < s.doc().device_count()) {
    draw_device(s.selected());
    ImGui::Separator();
    draw_model_and_sensor(s.selected());
  } else {
    ImGui::TextDisabled("Select a controller in the scene or the list to edit it.");
  }
}

void InspectorPanel::draw_device(int index) {
  LayoutState& s = *state_;
  const LayoutDevice& d = s.layout().devices[static_cast<size_t>(index)];
  // Re-sync the text fields when the selection or the document changed under them.
  if (buffers_for_ != index || buffers_head_ != s.history().head_id()) {
    std::snprintf(slot_buf_, sizeof slot_buf_, "%s", d.slot.c_str());
    std::snprintf(serial_buf_, sizeof serial_buf_, "%s", d.serial ? d.serial->c_str() : "");
    buffers_for_ = index;
    buffers_head_ = s.history().head_id();
  }
  ImGui::PushID(index);
  ImGui::SetNextItemWidth(160);
  ImGui::InputText("Slot", slot_buf_, sizeof slot_buf_);
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    s.report(rename_slot(s.upd_history(), index, slot_buf_), "Rename");
    buffers_for_ = -2;
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(140);
  ImGui::InputTextWithHint("Serial", "unassigned", serial_buf_, sizeof serial_buf_);
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    s.report(assign_serial(s.upd_history(), index, serial_buf_), "Assign serial");
    buffers_for_ = -2;
  }

  static const char* kUnits[kNumPoseParams] = {"%.1f mm", "%.1f mm", "%.1f mm", "%.2f°", "%.2f°", "%.2f°"};
  ImGui::TextDisabled("Pose (mm, degrees): drag, or click to type; ticked = locked");
  for (int k = 0; k < kNumPoseParams; ++k) {
    ImGui::PushID(k);
    bool locked = s.doc().locks[static_cast<size_t>(index)].locked[static_cast<size_t>(k)];
    if (ImGui::Checkbox("##lock", &locked)) s.report(set_device_lock(s.upd_history(), index, k, locked), "Lock");
    anchors_.remember("lock." + std::to_string(k));
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Lock %s: the optimiser and the scene handles leave it alone", pose_param_name(k));
    ImGui::SameLine();
    double v = d.pose.get(k);
    ImGui::SetNextItemWidth(200);
    const float speed = k < 3 ? 1.0f : 0.25f;
    if (type_into_pose_ == k) {
      ImGui::SetKeyboardFocusHere();  // on a drag field this starts text input
      type_into_pose_ = -1;
    }
    if (ImGui::DragScalar(pose_param_name(k), ImGuiDataType_Double, &v, speed, nullptr, nullptr, kUnits[k])) {
      DevicePose p = d.pose;
      p.set(k, v);
      preview_device_pose(s.upd_history(), index, p);
    }
    anchors_.remember("pose." + std::to_string(k));
    if (ImGui::IsItemHovered() && !ImGui::IsItemActive()) ImGui::SetTooltip("Drag to change, or click to type a value");
    const float threshold = ImGui::GetIO().MouseDragThreshold;
    if (ImGui::IsItemDeactivated() && !ImGui::IsItemDeactivatedAfterEdit() && !ImGui::GetIO().WantTextInput &&
        ImGui::GetIO().MouseDragMaxDistanceSqr[0] < threshold * threshold) {
      type_into_pose_ = k;
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) {
      if (commit_device_pose(s.upd_history(), index, std::string("Set ") + pose_param_name(k) + " of")) {
        s.set_status(s.history().undo_message());
      }
    }
    if (locked) {
      ImGui::SameLine();
      ImGui::TextDisabled("locked");
    }
    ImGui::PopID();
  }
  ImGui::TextDisabled("Offset %.2f, %.2f, %.2f mm (after the pose)", d.offset_mm.x(), d.offset_mm.y(), d.offset_mm.z());
  ImGui::PopID();
}

void InspectorPanel::draw_model_and_sensor(int index) {
  ImGui::PushID("model");
  if (scroll_to_model_) {
    ImGui::SetScrollHereY(0.0f);
    scroll_to_model_ = false;
  }
  draw_model_combo(index);
  draw_sensor_fields(index);
  const LayoutDevice& d = state_->layout().devices[static_cast<size_t>(index)];
  if (const SensorSpec* spec = sensor_catalogue().find(d.model)) draw_position_noise(*spec);
  draw_model_buttons(index);
  ImGui::PopID();
}

void InspectorPanel::draw_model_combo(int index) {
  LayoutState& s = *state_;
  const std::string slot = s.layout().devices[static_cast<size_t>(index)].slot;
  const std::string shown_model = s.layout().devices[static_cast<size_t>(index)].model;
  const SensorSpec* shown_spec = sensor_catalogue().find(shown_model);
  // As wide as the panel allows beside its label: the study's model has a long name.
  ImGui::SetNextItemWidth(-(ImGui::CalcTextSize("Model").x + ImGui::GetStyle().ItemInnerSpacing.x));
  if (ImGui::BeginCombo("Model", shown_spec ? shown_spec->name.c_str() : shown_model.c_str())) {
    for (const SensorSpec& m : sensor_catalogue().models) {
      if (ImGui::Selectable(m.name.c_str(), m.id == shown_model)) {
        s.report(set_device_model(s.upd_history(), index, m.id), "Model of " + slot);
      }
      anchors_.remember("model." + m.id);
    }
    ImGui::EndCombo();
  }
  anchors_.remember("model");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "What %s is (assets/sensors/sensors.json): its field of view, ranges and case.\n"
        "The values below are its model's; one you change overrides the model for %s only.",
        slot.c_str(), slot.c_str());
  }
}

// The sensor's values, read again (the combo may just have changed the model). A value that
// differs from the model's is an override (what the layout file stores for this controller).
void InspectorPanel::draw_sensor_fields(int index) {
  LayoutState& s = *state_;
  const LayoutDevice& d = s.layout().devices[static_cast<size_t>(index)];
  const std::string slot = d.slot;  // kept: the actions below replace the devices `d` is in
  const SensorSpec* spec = sensor_catalogue().find(d.model);
  const SensorModel model_sensor = spec ? spec->sensor : d.sensor;
  SensorModel sensor = d.sensor;
  struct Field {
    const char* key;  // anchor "sensor.<key>"
    const char* label;
    double* value;
    double model_value;
    const char* format;  // of the drag field
    const char* unit;    // of the model's value beside an override
    float speed;
  };
  const Field fields[] = {
      {"fov_long", "Field of view along x", &sensor.fov_long_deg, model_sensor.fov_long_deg, "%.0f°", "°", 0.5f},
      {"fov_short", "Field of view across (z)", &sensor.fov_short_deg, model_sensor.fov_short_deg, "%.0f°", "°", 0.5f},
      {"range_near", "Near range", &sensor.range_near_mm, model_sensor.range_near_mm, "%.0f mm", " mm", 1.0f},
      {"range", "Far range", &sensor.range_mm, model_sensor.range_mm, "%.0f mm", " mm", 2.0f},
      {"axis_cut", "Axis cut", &sensor.axis_cut_mm, model_sensor.axis_cut_mm, "%.0f mm", " mm", 2.0f},
  };
  ImGui::TextDisabled("Sensor of %s (drag, or double-click to type)", slot.c_str());
  bool changed = false, released = false;
  for (const Field& f : fields) {
    ImGui::PushID(f.key);
    ImGui::SetNextItemWidth(110);
    changed |= ImGui::DragScalar(f.label, ImGuiDataType_Double, f.value, f.speed, nullptr, nullptr, f.format);
    released |= ImGui::IsItemDeactivatedAfterEdit();
    anchors_.remember(std::string("sensor.") + f.key);
    if (*f.value != f.model_value) {
      char model_text[48];
      std::snprintf(model_text, sizeof model_text, "%.0f%s", f.model_value, f.unit);
      ImGui::SameLine();
      ImGui::TextColored(palette::kWarning, "overrides %s", model_text);
      anchors_.remember(std::string("override.") + f.key);
    }
    ImGui::PopID();
  }
  if (changed) preview_device_sensor(s.upd_history(), index, sensor);
  if (released) s.report(set_device_sensor(s.upd_history(), index, sensor), "Sensor of " + slot);
}

// Not a layout value (nothing to drag): how far this model's reported positions scatter, which
// the simulated rig adds to every point of a controller of this model. A no-break space keeps the
// figure and its unit on one line when the text wraps.
void InspectorPanel::draw_position_noise(const SensorSpec& spec) {
  char noise[160];
  if (spec.position_noise_sd_mm) {
    std::snprintf(noise, sizeof noise, "Position noise %.2f\u00a0mm SD per axis (published); the simulated rig uses it",
                  *spec.position_noise_sd_mm);
  } else {
    std::snprintf(noise, sizeof noise,
                  "Position noise: no published figure; the simulated rig uses %.0f\u00a0mm SD per axis",
                  kDefaultPositionNoiseSdMm);
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", noise);
  ImGui::PopStyleColor();
  anchors_.remember("position-noise");
}

// Reset to model (while the sensor overrides it) and Apply this model to all controllers.
void InspectorPanel::draw_model_buttons(int index) {
  LayoutState& s = *state_;
  const LayoutDevice& d = s.layout().devices[static_cast<size_t>(index)];
  const std::string slot = d.slot;
  const std::string model_id = d.model;  // kept: the actions below replace the devices `d` is in
  const SensorSpec* spec = sensor_catalogue().find(model_id);
  const SensorModel model_sensor = spec ? spec->sensor : d.sensor;
  const bool overridden = spec != nullptr && !(d.sensor == spec->sensor);
  ImGui::BeginDisabled(!overridden);
  if (ImGui::Button("Reset to model")) s.report(reset_device_sensor(s.upd_history(), index), "Reset " + slot);
  anchors_.remember("reset-sensor");
  ImGui::EndDisabled();
  ImGui::SameLine();
  bool everyone_is_this = spec != nullptr;
  for (const LayoutDevice& other : s.layout().devices) {
    everyone_is_this = everyone_is_this && other.model == model_id && other.sensor == model_sensor;
  }
  ImGui::BeginDisabled(everyone_is_this);
  if (ImGui::Button("Apply this model to all controllers")) {
    s.report(set_every_device_model(s.upd_history(), model_id), "Model of every controller");
  }
  anchors_.remember("model-to-all");
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip("Every controller becomes a %s, overrides dropped (one undo step)",
                      spec ? spec->name.c_str() : model_id.c_str());
  }
}

}  // namespace lmc::ui
