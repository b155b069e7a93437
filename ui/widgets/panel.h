#pragma once
// What every panel of a tab has: the child window it draws in, that window's ImGui id, and
// whether it is shown. A panel class derives from Panel, naming its window once; the tab says
// where the window goes (its size and frame) and draws the panel's body inside it:
//
//   if (const auto window = trials_.window(ImVec2(260, 0), true)) trials_.draw();
//
// so no tab repeats BeginChild / EndChild around a panel, and a hidden panel draws nothing.
#include <imgui.h>

#include <string>
#include <utility>

namespace lmc::ui {

class Panel {
 public:
  // The child window, open for the scope it lives in (EndChild when it ends); false while the
  // panel is hidden, when nothing was begun.
  class Window {
   public:
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;
    ~Window() {
      if (open_) ImGui::EndChild();
    }
    explicit operator bool() const { return open_; }

   private:
    friend class Panel;
    explicit Window(bool open) : open_(open) {}
    bool open_;
  };

  const std::string& window_id() const { return window_id_; }
  bool visible() const { return visible_; }
  void set_visible(bool on) { visible_ = on; }

  // Begins the panel's child window of `size` (0 on an axis: the rest of the region).
  [[nodiscard]] Window window(ImVec2 size = ImVec2(0, 0), bool border = false, ImGuiWindowFlags flags = 0) const {
    if (!visible_) return Window(false);
    ImGui::BeginChild(window_id_.c_str(), size, border, flags);
    return Window(true);
  }

 protected:
  explicit Panel(std::string window_id) : window_id_(std::move(window_id)) {}
  ~Panel() = default;
  Panel(const Panel&) = default;
  Panel& operator=(const Panel&) = default;

 private:
  std::string window_id_;
  bool visible_ = true;
};

}  // namespace lmc::ui
