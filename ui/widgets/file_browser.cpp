#include "ui/widgets/file_browser.h"

#include "ui/widgets/palette.h"

#include <imgui.h>

#include <cstdio>
#include <cstring>
#include <utility>

namespace lmc::ui {

FileBrowser::FileBrowser(std::string title, std::string extension)
    : title_(std::move(title)), extension_(extension), model_(std::filesystem::current_path(), std::move(extension)) {}

void FileBrowser::open(Mode mode, const std::filesystem::path& start_dir, const std::string& file_name) {
  mode_ = mode;
  model_.go_to(start_dir);
  std::snprintf(name_, sizeof name_, "%s", file_name.c_str());
  open_ = true;
  request_popup_ = true;
}

std::optional<std::filesystem::path> FileBrowser::draw() {
  if (!open_) return std::nullopt;
  if (request_popup_) {
    ImGui::OpenPopup(title_.c_str());
    request_popup_ = false;
  }
  std::optional<std::filesystem::path> chosen;
  ImGui::SetNextWindowSize(ImVec2(560, 420), ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal(title_.c_str(), nullptr)) {
    ImGui::TextDisabled("Folder");
    ImGui::SameLine();
    ImGui::TextUnformatted(model_.directory().string().c_str());
    if (!model_.error().empty()) ImGui::TextColored(palette::kError, "%s", model_.error().c_str());
    const float footer = ImGui::GetFrameHeightWithSpacing() * 2 + 8;
    ImGui::BeginChild("##entries", ImVec2(0, -footer), true);
    if (ImGui::Selectable("..  (parent folder)", false, ImGuiSelectableFlags_DontClosePopups)) model_.enter("..");
    std::string enter_dir;
    for (const BrowserEntry& e : model_.entries()) {
      char label[320];
      if (e.is_directory) {
        std::snprintf(label, sizeof label, "[%s]", e.name.c_str());
      } else {
        std::snprintf(label, sizeof label, "%s", e.name.c_str());
      }
      const bool is_sel = !e.is_directory && e.name == name_;
      if (ImGui::Selectable(label, is_sel,
                            ImGuiSelectableFlags_DontClosePopups | ImGuiSelectableFlags_AllowDoubleClick)) {
        if (e.is_directory) {
          enter_dir = e.name;
        } else {
          std::snprintf(name_, sizeof name_, "%s", e.name.c_str());
          if (ImGui::IsMouseDoubleClicked(0)) chosen = model_.path_of(name_);
        }
      }
    }
    ImGui::EndChild();
    if (!enter_dir.empty()) model_.enter(enter_dir);
    ImGui::SetNextItemWidth(-1);
    const bool enter =
        ImGui::InputTextWithHint("##name", "file name", name_, sizeof name_, ImGuiInputTextFlags_EnterReturnsTrue);
    const char* ok_label = mode_ == Mode::kOpen ? "Open" : "Save";
    const bool ok = ImGui::Button(ok_label, ImVec2(100, 0)) || enter;
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel", ImVec2(100, 0));
    if (ok && name_[0] != '\0') {
      std::filesystem::path p = model_.path_of(name_);
      if (mode_ == Mode::kSave && p.extension().empty()) p += extension_;
      chosen = p;
    }
    if (chosen || cancel) {
      open_ = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  } else {
    open_ = false;
  }
  return chosen;
}

}  // namespace lmc::ui
