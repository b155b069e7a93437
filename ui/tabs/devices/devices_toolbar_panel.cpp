#include "ui/tabs/devices/devices_toolbar_panel.h"

#include <imgui.h>

#include <cstdio>
#include <string>
#include <string_view>

#include "core/common/paths.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {

void DevicesToolbarPanel::draw() {
  anchors_.clear();  // only what this frame drew
  DevicesState& s = *state_;
  DevicesViewModel& vm = s.view();
  follow_running_backend();
  ImGui::TextUnformatted("Backend");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(110);
  if (ImGui::BeginCombo("##backend", backend_choice_ == 0 ? "sim" : backend_choice_ == 1 ? "leapc" : "replay")) {
    if (ImGui::Selectable("sim", backend_choice_ == 0)) backend_choice_ = 0;
    // Always offered: Start looks for Ultraleap's library and says where it looked when it is missing.
    if (ImGui::Selectable("leapc", backend_choice_ == 1)) backend_choice_ = 1;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Ultraleap controllers through LeapC: the library is looked for at each Start");
    if (ImGui::Selectable("replay", backend_choice_ == 2)) backend_choice_ = 2;
    ImGui::EndCombo();
  }
  if (backend_choice_ == 2) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(260);
    ImGui::InputTextWithHint("##replay", "recording file (.raw.txt)", replay_, sizeof replay_);
  }
  ImGui::SameLine();
  ImGui::TextUnformatted("Layout");
  ImGui::SameLine();
  ImGui::TextColored(palette::kInfo, "%s", vm.layout().name.c_str());
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("The layout open in the Layout tab: open, edit or pick a preset there and the rig follows");
  }
  ImGui::SameLine();
  if (ImGui::Button("Save with serials...")) {
    save_browser_.open(FileBrowser::Mode::kSave, sessions_dir(), vm.layout().name + "-serials.json");
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Write this layout with every controller's serial in its slot, so each controller returns to "
        "its slot next time");
  }
  if (const auto chosen = save_browser_.draw()) s.save_layout_with_serials(*chosen);
  ImGui::SameLine();
  if (!vm.running()) {
    if (ImGui::Button("Start")) s.start(backend_spec());
    anchors_.remember("start");
  } else {
    if (ImGui::Button("Stop")) s.stop();
    anchors_.remember("stop");
    ImGui::SameLine();
    ImGui::Text("%s running %.0f s", vm.backend().c_str(), vm.running_seconds());
  }
}

void DevicesToolbarPanel::follow_running_backend() {
  const DevicesViewModel& vm = state_->view();
  if (!vm.running() || vm.backend() == followed_backend_) return;
  followed_backend_ = vm.backend();
  constexpr std::string_view kReplay = "replay:";
  if (followed_backend_.rfind(kReplay, 0) == 0) {
    backend_choice_ = 2;
    std::snprintf(replay_, sizeof replay_, "%s", followed_backend_.substr(kReplay.size()).c_str());
  } else {
    backend_choice_ = followed_backend_ == "leapc" ? 1 : 0;
  }
}

std::string DevicesToolbarPanel::backend_spec() const {
  if (backend_choice_ == 1) return "leapc";
  if (backend_choice_ == 2) return std::string("replay:") + replay_;
  return "sim";
}

}  // namespace lmc::ui
