#include "ui/widgets/placeholder_panel.h"

#include "ui/widgets/palette.h"

#include <imgui.h>

namespace lmc::ui {

void draw_placeholder_panel(const char* heading, const std::string& purpose, const std::vector<std::string>& planned) {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float width = avail.x < 720.0f ? avail.x : 720.0f;
  ImGui::SetCursorPosX(ImGui::GetCursorPosX() + (avail.x - width) * 0.5f);
  ImGui::BeginChild("placeholder_card", ImVec2(width, 0), true);
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextColored(palette::kInfo, "%s", heading);
  ImGui::Separator();
  ImGui::TextUnformatted(purpose.c_str());
  ImGui::Spacing();
  ImGui::TextDisabled("What this tab will hold:");
  for (const auto& item : planned) ImGui::BulletText("%s", item.c_str());
  ImGui::PopTextWrapPos();
  ImGui::EndChild();
}

}  // namespace lmc::ui
