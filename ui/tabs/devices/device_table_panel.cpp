#include "ui/tabs/devices/device_table_panel.h"

#include <imgui.h>

#include <string>
#include <vector>

#include "ui/widgets/imgui_colour.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {

void DeviceTablePanel::draw() {
  const DevicesViewModel& vm = state_->view();
  const auto& rows = vm.rows();
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("devices", 12, flags)) return;
  for (const char* h :
       {"", "Serial", "Slot", "Backend", "Model", "Mode", "Status", "Rate", "Hand", "Frame age", "Frames", "Dropped"})
    ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  const auto slots = vm.slot_choices();
  for (const auto& r : rows) draw_row(r, slots);
  ImGui::EndTable();
  if (rows.empty()) ImGui::TextDisabled(vm.running() ? "waiting for devices..." : "no backend running: press Start");
  // A controller the layout points away from the hand shows "no hand" forever: say it is the layout.
  ImGui::PushTextWrapPos(0.0F);
  for (const std::string& w : vm.layout_warnings()) ImGui::TextColored(palette::kWarning, "%s", w.c_str());
  ImGui::PopTextWrapPos();
}

// A controller's row: its slot's colour, serial, slot (a dropdown assigns it), backend, model,
// tracking mode, status and its stream's numbers.
void DeviceTablePanel::draw_row(const DeviceRow& r, const std::vector<std::string>& slots) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  const ImVec2 p = ImGui::GetCursorScreenPos();
  ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + 2), ImVec2(p.x + 14, p.y + 14),
                                            device_colour_u32(r.colour, r.slot.empty() ? 0.3F : 1.0F));
  ImGui::Dummy(ImVec2(14, 14));
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(r.serial.c_str());
  ImGui::TableNextColumn();
  ImGui::SetNextItemWidth(90);
  const std::string id = "##slot" + r.serial;
  if (ImGui::BeginCombo(id.c_str(), r.slot.empty() ? "-" : r.slot.c_str())) {
    for (const auto& slot : slots) {
      if (ImGui::Selectable(slot.c_str(), slot == r.slot)) state_->assign(r.serial, slot);
    }
    ImGui::EndCombo();
  }
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(r.backend.c_str());
  ImGui::TableNextColumn();
  if (r.model.empty()) {
    ImGui::TextDisabled("-");
  } else if (!r.model_warning.empty()) {
    // Another model than its slot's: the layout's visibility does not hold for it.
    ImGui::TextColored(palette::kWarning, "%s (!)", r.model.c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.model_warning.c_str());
  } else {
    ImGui::TextUnformatted(r.model.c_str());
  }
  ImGui::TableNextColumn();
  // The tracking mode the service reports: anything but what the layout implies is a warning
  // in the device messages; here it is just shown.
  if (r.tracking_mode.empty())
    ImGui::TextDisabled("-");
  else
    ImGui::TextUnformatted(r.tracking_mode.c_str());
  ImGui::TableNextColumn();
  if (r.warn)
    ImGui::TextColored(palette::kWarning, "%s", r.status.c_str());
  else
    ImGui::TextUnformatted(r.status.c_str());
  ImGui::TableNextColumn();
  ImGui::Text("%.0f Hz", r.rate_hz);
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(r.hand_present ? "yes" : "no");
  ImGui::TableNextColumn();
  if (r.age_ms < 0)
    ImGui::TextDisabled("-");
  else
    ImGui::Text("%.0f ms", r.age_ms);
  ImGui::TableNextColumn();
  ImGui::Text("%lld", static_cast<long long>(r.frames));
  ImGui::TableNextColumn();
  ImGui::Text("%lld", static_cast<long long>(r.dropped));
}

}  // namespace lmc::ui
