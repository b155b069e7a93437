#pragma once
// Which monitor the subject screen goes to, and where on it. The subject faces a second monitor
// on a lab bench: it opens there when there is one (the first monitor that is not the primary,
// where the operator's workbench is), on the one the operator picked in the Record tab (or saved
// from an earlier session, by name), and, with a single monitor, as a window beside the
// workbench (subject_window_placement.h). When the monitor it is on goes away (a projector
// unplugged), the same rule places it again on what is left. Pure: monitors in, a place out.
#include <optional>
#include <string>
#include <vector>

#include "ui/model/record/subject_window_placement.h"

namespace lmc::ui {

struct Monitor {
  std::string name;  // as the system names it ("HDMI-1"; on Windows often "Generic PnP Monitor")
  ScreenRect rect;   // its position and size on the desktop
  bool primary = false;
  bool operator==(const Monitor&) const = default;
};

// "HDMI-1 (1920x1080)", "eDP-1 (1920x1080, primary)": the Record tab's dropdown list.
std::string monitor_label(const Monitor& m);
// "2: 1920x1080", "1: 1920x1080, primary" (index + 1): the closed dropdown, which has no room for
// Windows' names ("Generic Non-PnP Monitor").
std::string monitor_short_label(int index, const Monitor& m);

// The monitor a saved choice means now: the same name at the same place, else the only one of
// that name. -1 when it is not connected (or two of that name moved).
int find_monitor(const std::vector<Monitor>& monitors, const Monitor& saved);

// The monitor the subject screen goes to: `chosen` when it indexes `monitors` (the dropdown,
// --subject-screen N), else the saved one when connected, else the first that is not the primary,
// else the primary. -1 with no monitors.
int choose_subject_monitor(const std::vector<Monitor>& monitors, int chosen, const std::optional<Monitor>& saved);

struct SubjectScreenPlace {
  int monitor = -1;             // index into the monitors; -1 when none is known
  bool covers_monitor = false;  // borderless over the whole monitor; else a window at `rect`
  ScreenRect rect;
  bool operator==(const SubjectScreenPlace&) const = default;
};

// Where the subject screen opens: over the chosen monitor unless `windowed` (then, or with no
// monitor, at subject_window_rect: where the operator left it, else beside their window).
SubjectScreenPlace place_subject_screen(const std::vector<Monitor>& monitors, int monitor, bool windowed,
                                        const ScreenRect& operator_window, const std::optional<ScreenRect>& remembered);

// Whether a subject screen placed on `on` must be placed again: that monitor is gone or has moved.
bool subject_monitor_gone(const std::vector<Monitor>& monitors, const Monitor& on);

// The user's settings for the subject screen, one line each in subject_window.txt: where the
// operator left the window ("x y width height", the line of subject_window_placement.h) and the
// monitor they picked ("monitor x y width height NAME"). A line that does not parse is ignored.
struct SubjectScreenSettings {
  std::optional<ScreenRect> window;
  std::optional<Monitor> monitor;
  bool operator==(const SubjectScreenSettings&) const = default;
};
std::string subject_screen_settings_text(const SubjectScreenSettings& settings);
SubjectScreenSettings parse_subject_screen_settings(const std::string& text);

}  // namespace lmc::ui
