#pragma once
// The workbench's frame: main menu, tab bar, status bar, help and the optional frame-time
// readout. It owns the tabs (from the registry) and what they share (WorkbenchContext: the one
// layout and the one live rig), and knows nothing about what they draw: the File menu forwards
// FileCommands to the tab that owns a document, and each tab reports through its own status sink.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/app/help_window.h"
#include "ui/app/tab_status_sink.h"
#include "ui/model/shell/recent_files.h"
#include "ui/model/shell/status_board.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/tab.h"

namespace lmc::ui {

// What the command line asks of the shell at start-up.
struct ShellStartup {
  std::string tab;  // the tab shown first ("" = the first)
  std::optional<RecordStartup> record;
  std::vector<std::filesystem::path> review;  // `--review DIR…`: opened in the Review tab
  // `--subject-screen [MONITOR|window]`: the Record tab's subject screen opens at start-up.
  std::optional<SubjectScreenRequest> subject_screen;
  // Where the recent-files list is kept; empty = nothing is read or written (captures, tests).
  std::filesystem::path recent_files_path;
};

// The newcomer's first step, shown in the status bar until the first click or key press.
inline constexpr const char* kNewcomerHint =
    "Start here: drag a controller in the 3D view to see which fingers it loses, or open the Record tab "
    "to run a session on the simulated rig. F1 for help.";

class WorkbenchShell final {
 public:
  explicit WorkbenchShell(ShellStartup startup = {});
  ~WorkbenchShell();
  WorkbenchShell(const WorkbenchShell&) = delete;
  WorkbenchShell& operator=(const WorkbenchShell&) = delete;

  // One frame: update every tab, then draw the shell and the active tab (full viewport).
  void frame();

  // Select a tab by id for the next frame; false when no such tab.
  bool select_tab(const std::string& id);
  Tab& tab(size_t i) { return *tabs_[i]; }
  size_t tab_count() const { return tabs_.size(); }
  const std::string& active_tab_id() const { return active_id_; }
  const StatusBoard& status_board() const { return status_; }
  const RecentFiles& recent_files() const { return recent_; }
  // What the tabs share; the window loop reads the subject screen's link from it.
  WorkbenchContext& context() { return *context_; }

  std::string window_title() const;
  bool quit_requested() const { return quit_requested_; }
  // Called when the window's close button is pressed: asks first when a trial records (stop and
  // keep it, or keep recording) or work is unsaved.
  void request_quit();
  // What records now in any tab ("" when nothing does).
  std::string recording_now() const;
  bool any_unsaved() const;
  void open_help(HelpWindow::Section section = HelpWindow::Section::kWalkthrough) { help_.open(section); }
  bool help_open() const { return help_.is_open(); }

 private:
  void draw_menu();
  void draw_file_menu();
  void draw_status_bar(float height);
  void draw_quit_prompt();
  void handle_shell_keys();
  // The tab the File menu talks to: the active one when it has a document, else the first that does.
  int document_tab() const;
  int tab_index(const std::string& id) const;
  // Files a tab opened or saved since the last frame join the recent list (and its file).
  void track_recent_files();

  // Before tabs_: the tabs hold references into them, so they are destroyed after the tabs.
  std::unique_ptr<WorkbenchContext> context_ = std::make_unique<WorkbenchContext>();
  StatusBoard status_{kNewcomerHint};
  std::vector<std::unique_ptr<TabStatusSink>> sinks_;
  std::vector<std::unique_ptr<Tab>> tabs_;
  std::vector<std::string> ids_;
  std::vector<std::optional<std::filesystem::path>> last_document_paths_;
  RecentFiles recent_;
  std::filesystem::path recent_files_path_;
  HelpWindow help_;
  std::string active_id_;
  std::string pending_select_;
  bool show_frame_time_ = false;
  // LMC_STATUS_TRACE=FILE: every status line shown, as "<tab>\t<text>", for tests that drive the
  // real window and must read what the operator read.
  std::ofstream status_trace_;
  std::string status_traced_;
  bool quit_requested_ = false;
  bool quit_prompt_open_ = false;
  std::string recording_prompt_;  // what records, while the recording question is to be asked or open
  bool quit_after_stop_ = false;  // the operator chose "stop and keep": quit once nothing records
  std::chrono::steady_clock::time_point last_frame_start_{};
  double frame_cpu_ms_ = 0.0;
};

}  // namespace lmc::ui
