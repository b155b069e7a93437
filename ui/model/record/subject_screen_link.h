#pragma once
// What the Record tab and the subject screen's window share, kept in the workbench
// context: the tab publishes the view and the operator's choice (open, which monitor, windowed);
// the platform side opens or closes the window to match, fills in the monitors it sees and says
// why it could not open one. UI thread only.
#include <optional>
#include <string>
#include <vector>

#include "ui/model/record/subject_view.h"

namespace lmc::ui {

struct SubjectScreenLink {
  // ---- set by the Record tab ----
  SubjectView view;
  double recording_s = 0;  // how far into the trial being recorded (0 outside one)
  bool open = false;
  int monitor = -1;  // index into monitors; -1: the bench decides (choose_subject_monitor)
  // The operator's choice of a plain window over covering the monitor; unset until they make one,
  // and then the bench decides (subject_screen_windowed).
  std::optional<bool> windowed;
  // ---- set by the window's side ----
  std::vector<std::string> monitors;        // monitor_label() of each
  std::vector<std::string> monitor_shorts;  // monitor_short_label() of each
  int placed_monitor = -1;                  // where it is (or would open): the dropdown shows it
  bool shown = false;                       // a window is up and drawing
  std::string problem;                      // why the last attempt to open it failed ("" = none)
};

// `lmc-workbench --subject-screen [MONITOR|window]`: a number picks the monitor (0 = the primary;
// none: the bench decides), "window" a plain window. nullopt with `error` set for anything else.
struct SubjectScreenRequest {
  int monitor = -1;
  bool windowed = false;
};
std::optional<SubjectScreenRequest> parse_subject_screen_arg(const std::string& arg, std::string& error);

// Opens the link as the command line asked: "window" chooses a window, a monitor number chooses
// to cover that monitor, neither leaves the choice to the bench.
void apply_subject_screen_request(SubjectScreenLink& link, const SubjectScreenRequest& request);

// Whether the subject screen is a plain window rather than covering its monitor: always a window
// on a bench with one monitor (or none seen yet), where covering the only monitor would hide the
// operator's own window; with two or more, the operator's choice when made, else the whole monitor.
bool subject_screen_windowed(const SubjectScreenLink& link);

}  // namespace lmc::ui
