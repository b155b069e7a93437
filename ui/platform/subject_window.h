#pragma once
// The subject screen's window: a second GLFW window, borderless and covering one
// monitor (or a plain window for a one-monitor bench), with its own Dear ImGui context — ImGui 1.86
// has no multi-viewport — and its own large fonts. Its GL context shares objects with the main
// window's, so textures made there can be shown here. It never takes the keyboard focus from the
// operator's window and installs no input callbacks: the subject screen has no controls.
#include <functional>
#include <string>
#include <vector>

#include "ui/model/record/subject_screen_monitor.h"

struct GLFWwindow;
struct ImGuiContext;
struct ImFont;

namespace lmc::ui {

// The monitors GLFW sees now (GLFW must be initialised: the main window exists). The first is
// the primary one.
std::vector<Monitor> list_monitors();
// Goes up by one each time a monitor is connected or disconnected (GLFW's monitor callback,
// installed by the first call).
int monitor_changes();
// Where `window` is on the desktop: its position and size in screen coordinates.
void window_placement(GLFWwindow* window, int& x, int& y, int& width, int& height);

struct SubjectWindowOptions {
  // Where it opens on the desktop: a monitor's rectangle to cover, borderless, or (windowed) a
  // decorated window's (subject_screen_monitor.h chooses it).
  ScreenRect place{40, 40, 1024, 640};
  bool windowed = false;
  Monitor on;                 // the monitor it covers or was placed on (empty name: none known)
  bool visible = true;        // false for --capture
  int width = 0, height = 0;  // with !visible: the picture's size
  // > 0: the normal font's size in pixels (large and huge keep their ratio to it). The off-screen
  // figure pictures (offscreen_png.h) use the same window at a figure's text size.
  float normal_font_px = 0;
};

struct SubjectFonts {
  ImFont* normal = nullptr;
  ImFont* large = nullptr;  // the cue
  ImFont* huge = nullptr;   // the countdown and headline
};

class SubjectWindow {
 public:
  // Throws std::runtime_error with GLFW's message when the window cannot be made.
  SubjectWindow(GLFWwindow* share, const SubjectWindowOptions& options);
  ~SubjectWindow();
  SubjectWindow(const SubjectWindow&) = delete;
  SubjectWindow& operator=(const SubjectWindow&) = delete;

  // True once the operator closed the (windowed) subject screen with its title bar.
  bool closed_by_user() const;
  const SubjectWindowOptions& options() const { return options_; }
  // Where the window is now (the operator may have moved or resized it): x, y, width, height.
  void placement(int& x, int& y, int& width, int& height) const;
  // One frame: makes this window's GL and ImGui contexts current, runs `body` inside its ImGui
  // frame, renders; writes the picture to `png_path` when given; swaps; then puts the caller's
  // GL and ImGui contexts back.
  void frame(const std::function<void(const SubjectFonts&)>& body, const std::string& png_path = {});

 private:
  GLFWwindow* window_ = nullptr;
  ImGuiContext* imgui_ = nullptr;
  SubjectFonts fonts_;
  SubjectWindowOptions options_;
};

}  // namespace lmc::ui
