#include "ui/tabs/layout/inspector_panel.h"

#include <imgui.h>

#include <cstdio>

namespace lmc::ui {

void InspectorPanel::draw() {
  anchors_.clear();
  LayoutTabState& s = *state_;
  const Layout& l = s.layout();
  ImGui::TextDisabled("Controllers (%d of 1-%d)", l.device_count(), kMaxDevices);
  ImGui::BeginChild("##devices", ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * std::min(l.device_count(), 5) + 8),
                    true);
  for (int i = 0; i < l.device_count(); ++i) {
    const LayoutDevice& d = l.devices[static_cast<size_t>(i)];
    char label[160];
    std::snprintf(label, sizeof label, "%-6s %-10s x %7.1f  z %7.1f  rx %6.1f  ry %6.1f##dev%d", d.slot.c_str(),
                  d.serial ? d.serial->c_str() : "", d.pose.x_mm, d.pose.z_mm, d.pose.rx_deg, d.pose.ry_deg, i);
    if (ImGui::Selectable(label, s.selected == i)) s.select(i);
  }
  ImGui::EndChild();
  ImGui::BeginDisabled(l.device_count() >= kMaxDevices);
  if (ImGui::Button("Add controller")) {
    if (s.report(add_device(s.upd_history()), "Add controller")) s.select(s.doc().device_count() - 1);
  }
  anchors_.remember("add");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(s.selected < 0 || l.device_count() <= 1);
  if (ImGui::Button("Remove selected")) s.report(remove_device(s.upd_history(), s.selected), "Remove controller");
  anchors_.remember("remove");
  ImGui::EndDisabled();

  ImGui::Separator();
  if (s.selected >= 0 && s.selected < s.doc().device_count()) {
    draw_device(s.selected);
  } else {
    ImGui::TextDisabled("Select a controller in the scene or the list to edit it.");
  }
  ImGui::Separator();
  draw_sensor();
}

void InspectorPanel::draw_device(int index) {
  LayoutTabState& s = *state_;
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

void InspectorPanel::draw_sensor() {
  LayoutTabState& s = *state_;
  // Edits every controller at once (their model ids stay, the values become overrides).
  SensorModel sensor = s.layout().devices.front().sensor;
  ImGui::TextDisabled("Sensor model (all controllers)");
  bool changed = false;
  ImGui::SetNextItemWidth(120);
  changed |= ImGui::DragScalar("range", ImGuiDataType_Double, &sensor.range_mm, 2.0f, nullptr, nullptr, "%.0f mm");
  const bool done_range = ImGui::IsItemDeactivatedAfterEdit();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  changed |= ImGui::DragScalar("long", ImGuiDataType_Double, &sensor.fov_long_deg, 0.5f, nullptr, nullptr, "%.0f°");
  const bool done_long = ImGui::IsItemDeactivatedAfterEdit();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  changed |= ImGui::DragScalar("short", ImGuiDataType_Double, &sensor.fov_short_deg, 0.5f, nullptr, nullptr, "%.0f°");
  const bool done_short = ImGui::IsItemDeactivatedAfterEdit();
  if (changed) set_all_sensors(s.upd_history().upd_scratch().layout, sensor);
  if (done_range || done_long || done_short) {
    const SensorModel edited = s.doc().layout.devices.front().sensor;
    s.report(set_sensor_model(s.upd_history(), edited), "Sensor model");
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Study defaults: 600 mm, 150° × 120° (docs/algorithms/visibility.md)\nDrag to change; double-click to type");
  }
}

}  // namespace lmc::ui
