#pragma once
// The one GLFW window with an OpenGL 3.3 core context and Dear ImGui on top of it.
#include <functional>
#include <optional>
#include <string>

#include "ui/model/shell/ui_scale.h"

struct GLFWwindow;

namespace lmc::ui {

struct WindowOptions {
  int width = 1280;  // in ImGui units: the window has width × the UI scale pixels (ui_scale.h)
  int height = 800;
  bool visible = true;  // false for --capture (a hidden window still renders and reads back)
  std::string title = "LMC Workbench";
  std::optional<float> ui_scale{};  // --ui-scale; unset: the screen's content scale, followed as it changes
};

class GlWindow {
 public:
  // Throws std::runtime_error with GLFW's own message when no display or GL 3.3 is available.
  explicit GlWindow(const WindowOptions& options);
  ~GlWindow();
  GlWindow(const GlWindow&) = delete;
  GlWindow& operator=(const GlWindow&) = delete;

  bool should_close() const;
  void set_should_close(bool close);
  void set_title(const std::string& title);
  // Resizes the window to width × height ImGui units and waits (up to a second) until the display server reports the
  // new size, so the next frame lays out at it.
  void set_size(int units_wide, int units_high);
  void begin_frame();  // poll events, start an ImGui frame
  void end_frame();    // render ImGui into the back buffer (no swap)
  void present();      // swap buffers
  int framebuffer_width() const;
  int framebuffer_height() const;
  // The refresh rate of the primary monitor's current mode; 0 when GLFW cannot say.
  int monitor_refresh_hz() const;
  // Whether this window's OpenGL renderer draws on the CPU (is_software_renderer).
  bool software_renderer() const;
  // Back buffer → PNG (call between end_frame and present). Throws on failure.
  void save_png(const std::string& path) const;
  GLFWwindow* handle() const { return window_; }
  const UiScale& ui_scale() const { return scale_; }

 private:
  static void on_content_scale(GLFWwindow* window, float x, float y);
  // The font atlas at the scale the window's content scale (or the override) asks for, rebuilt
  // before a frame starts, never inside one.
  void follow_content_scale();
  void load_fonts();
  // ImGui lays out in units, the window has pixels: after the GLFW backend's frame start.
  void to_ui_units() const;

  GLFWwindow* window_ = nullptr;
  std::string ini_path_;
  std::optional<float> scale_override_;
  UiScale scale_;
  bool content_scale_changed_ = false;
};

// The current GL context's back buffer (w × h) → PNG. Throws on failure.
void write_back_buffer_png(const std::string& path, int width, int height);

}  // namespace lmc::ui
