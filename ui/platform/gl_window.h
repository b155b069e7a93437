#pragma once
// The one GLFW window with an OpenGL 3.3 core context and Dear ImGui on top of it.
#include <functional>
#include <string>

struct GLFWwindow;

namespace lmc::ui {

struct WindowOptions {
  int width = 1280;
  int height = 800;
  bool visible = true;  // false for --capture (a hidden window still renders and reads back)
  std::string title = "LMC Workbench";
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
  // Resizes the window and waits (up to a second) until the display server reports the new size,
  // so the next frame lays out at it.
  void set_size(int width, int height);
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

 private:
  GLFWwindow* window_ = nullptr;
  std::string ini_path_;
};

// The current GL context's back buffer (w × h) → PNG. Throws on failure.
void write_back_buffer_png(const std::string& path, int width, int height);

}  // namespace lmc::ui
