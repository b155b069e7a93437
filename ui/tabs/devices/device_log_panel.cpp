#include "ui/tabs/devices/device_log_panel.h"

#include <imgui.h>

namespace lmc::ui {

void DeviceLogPanel::draw() {
  ImGui::TextDisabled("Device messages");
  for (const auto& m : state_->view().messages()) ImGui::TextWrapped("%s", m.c_str());
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0F);
}

}  // namespace lmc::ui
