#include "ui/platform/offscreen_png.h"

#include <imgui.h>

#include "ui/platform/subject_window.h"

namespace lmc::ui {

void render_offscreen_png(GLFWwindow* share, int width, int height, const std::string& png_path,
                          const std::function<void()>& draw) {
  SubjectWindowOptions options;
  options.visible = false;
  options.width = width;
  options.height = height;
  options.normal_font_px = 15.0F;
  SubjectWindow window(share, options);
  const auto body = [&](const SubjectFonts& fonts) {
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize);
    ImGui::Begin("##picture", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
    ImGui::PushFont(fonts.normal);
    draw();
    ImGui::PopFont();
    ImGui::End();
  };
  // The first frame lays the window out (ImGui sizes items from the previous frame); the second
  // is the picture.
  window.frame(body);
  window.frame(body, png_path);
}

}  // namespace lmc::ui
