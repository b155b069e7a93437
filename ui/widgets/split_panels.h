#pragma once
// Two side-by-side child regions with a draggable splitter between them: ImGui 1.86 has no
// docking, so every tab that wants "main view | side panels" needs this scaffolding. The right
// panel keeps its width while the window resizes (the main view takes the change), and neither
// side can be dragged smaller than its minimum.
#include <imgui.h>

#include <functional>

namespace lmc::ui {

struct SplitPanelsOptions {
  float min_left = 300.0f;  // the splitter stops this far from the left edge
  float min_right = 320.0f;
  float splitter_width = 6.0f;
  ImGuiWindowFlags left_flags = ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse;
  ImGuiWindowFlags right_flags = ImGuiWindowFlags_None;
};

class SplitPanels {
 public:
  explicit SplitPanels(float right_width, SplitPanelsOptions options = {})
      : right_width_(right_width), options_(options) {}

  // Fills the available region: `left` and `right` draw inside child windows "##left" and
  // "##right" (their ids are stable so panel tests can find them).
  void draw(const std::function<void()>& left, const std::function<void()>& right);

  float right_width() const { return right_width_; }
  void set_right_width(float w) { right_width_ = w; }

 private:
  float right_width_;
  SplitPanelsOptions options_;
};

}  // namespace lmc::ui
