#pragma once
// The workbench's frame: main menu, tab bar, status bar and the optional frame-time readout.
// It owns the tabs (from the registry) and what they share (WorkbenchContext: the one layout and
// the one live rig), and knows nothing about what they draw.
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/model/workbench_context.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/tab.h"

namespace lmc::ui {

// What the command line asks of the shell at start-up.
struct ShellStartup {
  std::string tab;  // the tab shown first ("" = the first)
  std::optional<RecordStartup> record;
};

class WorkbenchShell final : public StatusSink {
 public:
  explicit WorkbenchShell(ShellStartup startup = {});
  ~WorkbenchShell() override;

  // One frame: update every tab, then draw the shell and the active tab (full viewport).
  void frame();

  void set_status(const std::string& text, bool is_error) override;

  // Select a tab by id for the next frame; false when no such tab.
  bool select_tab(const std::string& id);
  Tab& tab(size_t i) { return *tabs_[i]; }
  size_t tab_count() const { return tabs_.size(); }
  const std::string& active_tab_id() const { return active_id_; }

  std::string window_title() const;
  bool quit_requested() const { return quit_requested_; }
  // Called when the window's close button is pressed: asks first when work is unsaved.
  void request_quit();
  bool any_unsaved() const;

 private:
  void draw_menu();
  void draw_status_bar(float height);
  void draw_quit_prompt();

  // Before tabs_: the tabs hold references into it, so it is destroyed after them.
  std::unique_ptr<WorkbenchContext> context_ = std::make_unique<WorkbenchContext>();
  std::vector<std::unique_ptr<Tab>> tabs_;
  std::vector<std::string> ids_;
  std::string active_id_;
  std::string pending_select_;
  std::string status_text_ = "Ready.";
  bool status_is_error_ = false;
  bool show_frame_time_ = false;
  bool quit_requested_ = false;
  bool quit_prompt_open_ = false;
  bool show_about_ = false;
  std::chrono::steady_clock::time_point last_frame_start_{};
  double frame_cpu_ms_ = 0.0;
};

}  // namespace lmc::ui
