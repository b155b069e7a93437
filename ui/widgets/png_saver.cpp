#include "ui/widgets/png_saver.h"

#include <imgui.h>

#include <algorithm>

#include "core/common/paths.h"

namespace lmc::ui {

void PngSaver::draw(const char* id, const PictureRenderer& renderer, const std::string& default_name,
                    const std::function<void()>& picture) {
  ImGui::PushID(id);
  ImGui::BeginDisabled(!renderer);
  if (ImGui::Button("PNG...")) ImGui::OpenPopup("png_size");
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Save this picture as PNG at a size you choose (rendered off screen)");
  if (ImGui::BeginPopup("png_size")) {
    ImGui::SetNextItemWidth(90);
    ImGui::InputInt("width (px)", &width_, 100);
    ImGui::SetNextItemWidth(90);
    ImGui::InputInt("height (px)", &height_, 100);
    width_ = std::clamp(width_, 320, 4096);
    height_ = std::clamp(height_, 240, 4096);
    if (ImGui::Button("Choose file...")) {
      browser_.open(FileBrowser::Mode::kSave, sessions_dir(), default_name + ".png");
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  if (const auto chosen = browser_.draw()) {
    try {
      renderer(width_, height_, chosen->string(), picture);
      message_ = "wrote " + chosen->string();
    } catch (const std::exception& e) {
      message_ = std::string("PNG not written: ") + e.what();
    }
  }
  if (!message_.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", message_.c_str());
  }
  ImGui::PopID();
}

}  // namespace lmc::ui
