#pragma once
// Keeps the subject screen's window (ui/platform/subject_window.h) in step with what the Record
// tab asks for through the workbench context's SubjectScreenLink: opens it where
// subject_screen_monitor.h places it, moves it when the choice changes or its monitor is
// unplugged, closes it, and draws the tab's SubjectView in it each frame. The operator's monitor
// and where they left a windowed one are kept in the user's config (subject_window.txt).
// The window loop (interactive and --capture) calls frame() after the main window's frame.
#include <memory>
#include <string>
#include <vector>

#include "ui/model/record/subject_screen_link.h"
#include "ui/model/record/subject_screen_monitor.h"
#include "ui/platform/subject_window.h"

struct GLFWwindow;

namespace lmc::ui {

class SubjectScreen {
 public:
  // `hidden_width/height` > 0: --capture (a hidden window of that size, whatever the monitor).
  explicit SubjectScreen(GLFWwindow* main_window, int hidden_width = 0, int hidden_height = 0);
  ~SubjectScreen();
  SubjectScreen(const SubjectScreen&) = delete;
  SubjectScreen& operator=(const SubjectScreen&) = delete;

  // Opens, moves or closes the window to match `link`, then draws a frame (and writes it to
  // `png_path` when given). Reports back through `link` (monitors, shown, problem).
  void frame(SubjectScreenLink& link, const std::string& png_path = {});
  bool shown() const { return window_ != nullptr; }

 private:
  // A windowed subject screen's place goes to the user's config when it closes, so the next
  // session opens it where the operator put it (subject_window_placement.h).
  void remember_placement();
  // The monitor the operator picked in the Record tab, kept for the next session.
  void remember_monitor_choice(const SubjectScreenLink& link, const std::vector<Monitor>& monitors);
  void save_settings() const;
  // The open window no longer matches: closed in the tab, another monitor or mode chosen, or its
  // monitor unplugged.
  bool must_reopen(const SubjectScreenLink& link, const std::vector<Monitor>& monitors, int monitor, bool windowed);
  void open(SubjectScreenLink& link, const std::vector<Monitor>& monitors, int monitor, bool windowed);

  GLFWwindow* main_;
  int hidden_width_, hidden_height_;
  std::unique_ptr<SubjectWindow> window_;
  SubjectScreenSettings settings_;
  int monitor_choice_seen_ = -1;
  int monitor_changes_seen_ = 0;
};

}  // namespace lmc::ui
