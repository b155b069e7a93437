#pragma once
// Where the subject screen opens as a window (a bench with one monitor, or the operator's choice):
// where the operator last left it, else beside the workbench's window, else — the workbench
// fills the monitor — in the monitor's bottom-right corner at a third of its width, over the
// Record tab's 3D view rather than its buttons and note line. Never over the whole monitor: that
// is only for a second monitor (subject_screen_windowed). Pure arithmetic on screen rectangles.
#include <optional>
#include <string>
#include <vector>

namespace lmc::ui {

struct ScreenRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const ScreenRect&) const = default;
};

// `monitors` as GLFW lists them (the first is the primary); `monitor`: the chosen one (-1 or out of
// range: the one holding most of the operator's window); `remembered`: where the operator last
// left the window, used when it still lies mostly on a monitor.
ScreenRect subject_window_rect(const std::vector<ScreenRect>& monitors, int monitor, const ScreenRect& operator_window,
                               const std::optional<ScreenRect>& remembered);

// The remembered rectangle as one line of the user's config ("x y width height") and back;
// nullopt for anything else (a damaged file is ignored, not fatal).
std::string subject_window_rect_text(const ScreenRect& r);
std::optional<ScreenRect> parse_subject_window_rect(const std::string& text);

}  // namespace lmc::ui
