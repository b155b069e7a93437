#include "ui/app/capture.h"

#include <imgui.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>
#include <utility>

#include "ui/app/capture/tab_capture.h"
#include "ui/app/capture/text_fit_check.h"
#include "ui/app/subject_screen.h"
#include "ui/app/workbench_shell.h"
#include "ui/model/record/subject_stage_trace.h"
#include "ui/model/shell/frame_pacer.h"
#include "ui/platform/gl_window.h"
#include "ui/platform/offscreen_png.h"
#include "ui/platform/user_config.h"
#include "ui/tabs/tab_registry.h"

namespace lmc::ui {
namespace {

// Exports of pictures (the Review tab's PNG) render in a hidden window beside this one.
void install_picture_renderer(WorkbenchShell& shell, GlWindow& window) {
  shell.context().picture_renderer() = [&window](int w, int h, const std::string& png,
                                                 const std::function<void()>& draw) {
    render_offscreen_png(window.handle(), w, h, png, draw);
  };
}

// LMC_SUBJECT_TRACE=FILE: the end-to-end test reads what the subject screen showed, and when.
SubjectStageTrace subject_stage_trace_from_environment() {
  const char* file = std::getenv("LMC_SUBJECT_TRACE");
  return file != nullptr && *file != '\0' ? SubjectStageTrace(file) : SubjectStageTrace();
}

// After the shell's frame, while its ImGui context is current.
void trace_subject_screen(SubjectStageTrace& trace, const SubjectScreenLink& link) {
  trace.observe(link.view, link.recording_s, ImGui::GetTime());
}

// LMC_CAPTURE_HELP=walkthrough|shortcuts|about (1 = walkthrough) shows the Help window over
// every capture: menus are closed in captures, so this is the only way to look at it.
void open_help_from_environment(WorkbenchShell& shell) {
  const char* help = std::getenv("LMC_CAPTURE_HELP");
  if (help == nullptr || *help == '\0' || std::string(help) == "0") return;
  const std::string which = help;
  shell.open_help(which == "shortcuts" ? HelpWindow::Section::kShortcuts
                  : which == "about"   ? HelpWindow::Section::kAbout
                                       : HelpWindow::Section::kWalkthrough);
}

bool known_tabs(const std::vector<std::string>& ids) {
  for (const auto& id : ids) {
    bool known = false;
    for (const auto& info : tab_registry()) known = known || info.id == id;
    if (!known) {
      std::cerr << "lmc-workbench: unknown tab '" << id << "' (tabs: layout, devices, record, review)\n";
      return false;
    }
  }
  return true;
}

size_t tab_index(const std::string& id) {
  size_t index = 0;
  for (size_t i = 0; i < tab_registry().size(); ++i) {
    if (tab_registry()[i].id == id) index = i;
  }
  return index;
}

}  // namespace

int run_interactive(int width, int height, ShellStartup startup, std::optional<float> ui_scale) {
  GlWindow window(WindowOptions{width, height, true, "LMC Workbench", ui_scale});
  if (startup.recent_files_path.empty()) {
    if (const auto dir = user_config_dir(); !dir.empty()) startup.recent_files_path = dir / "recent_files.json";
  }
  WorkbenchShell shell(std::move(startup));
  install_picture_renderer(shell, window);
  SubjectScreen subject(window.handle());
  SubjectStageTrace trace = subject_stage_trace_from_environment();
  FramePacer pacer(window.monitor_refresh_hz(), window.software_renderer());
  std::string title;
  while (!shell.quit_requested()) {
    if (window.should_close()) {
      window.set_should_close(false);
      shell.request_quit();
    }
    window.begin_frame();
    shell.frame();
    trace_subject_screen(trace, shell.context().subject_screen());
    window.end_frame();
    window.present();
    subject.frame(shell.context().subject_screen());
    if (const std::string t = shell.window_title(); t != title) {
      title = t;
      window.set_title(title);
    }
    std::this_thread::sleep_until(pacer.next_frame_start(FramePacer::Clock::now()));
  }
  return 0;
}

namespace {

// One `--capture` run: the tabs in a hidden window, each set up by its script (capture/), then
// pictured at one or two sizes.
class CaptureRun {
 public:
  CaptureRun(const CaptureOptions& options, WorkbenchShell& shell, GlWindow& window, SubjectScreen& subject,
             std::vector<std::unique_ptr<TabCapture>>& scripts)
      : options_(options), shell_(shell), window_(window), subject_(subject), scripts_(scripts) {}

  // Every tab's pictures; the exit status run_capture() returns.
  int run(const std::vector<std::string>& ids) {
    for (const auto& id : ids) {
      Tab& tab = shell_.tab(tab_index(id));
      scripts_.push_back(make_tab_capture(tab, shell_.context()));
      TabCapture& script = *scripts_.back();
      shell_.select_tab(id);
      settle(script, script.prepare());
      take(id);
      for (const auto& extra : script.extra_captures()) {
        script.prepare_extra(extra);
        settle(script, 2);
        take(extra);
      }
    }
    for (const auto& script : scripts_) script->finish();
    if (status_ == 0 && cuts_ > 0) {
      std::cerr << "lmc-workbench: " << cuts_ << " piece(s) of text not shown whole (" << options_.dir
                << "/cut-text.txt)\n";
      return 3;
    }
    return status_;
  }

 private:
  // The shell's frame, with every script's hooks around it (the last one made is the tab shown).
  void shell_frame() {
    for (const auto& script : scripts_) script->before_frame(script == scripts_.back());
    shell_.frame();
    trace_subject_screen(trace_, shell_.context().subject_screen());
    for (const auto& script : scripts_) script->after_frame(script == scripts_.back());
  }

  void draw_frame() {
    window_.begin_frame();
    shell_frame();
    window_.end_frame();
    window_.present();
    subject_.frame(shell_.context().subject_screen());
  }

  // Let the tab settle: layout needs a couple of frames; background work (a heatmap, a simulated
  // rig, a trial) gets up to 20 s to finish so the picture shows real content. While it works, a
  // frame every 100 ms: nobody watches these frames, and under Xvfb each one is drawn by the CPU,
  // which the work itself and the tests beside it need.
  void settle(const TabCapture& script, int settle_frames) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    int frames = 0;
    while (frames < settle_frames + 3 || (script.busy() && std::chrono::steady_clock::now() < deadline)) {
      draw_frame();
      ++frames;
      if (script.busy()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }

  void check_text(const std::string& picture) {
    if (!options_.check_text) return;
    for (const CutText& cut : find_cut_text()) {
      if (!cut_list_.is_open()) cut_list_.open(std::filesystem::path(options_.dir) / "cut-text.txt");
      const std::string line = picture + ": " + describe(cut);
      cut_list_ << line << "\n";
      std::cerr << "lmc-workbench: text cut in " << line << "\n";
      ++cuts_;
    }
  }

  void take_at_size(const std::string& name) {
    const auto path = (std::filesystem::path(options_.dir) / (name + ".png")).string();
    window_.begin_frame();
    shell_frame();
    window_.end_frame();
    const bool of_subject = name.rfind("subject-screen", 0) == 0;
    if (!of_subject) {
      window_.save_png(path);
      check_text(name);
    }
    window_.present();
    subject_.frame(shell_.context().subject_screen(), of_subject ? path : std::string());
    if (of_subject && !subject_.shown()) {
      std::cerr << "lmc-workbench: the subject screen was not open (" << shell_.context().subject_screen().problem
                << "), so " << path << " was not written\n";
      status_ = 1;
      return;
    }
    std::cout << "wrote " << path << "\n";
  }

  // The second size (a laptop's 1024 x 700) shows the same state: only the layout changes, so a
  // few frames settle it. The subject screen has its own window and size.
  void take(const std::string& name) {
    take_at_size(name);
    const bool also = options_.also_width > 0 && options_.also_height > 0;
    if (!also || name.rfind("subject-screen", 0) == 0) return;
    window_.set_size(options_.also_width, options_.also_height);
    for (int i = 0; i < 3; ++i) draw_frame();
    take_at_size(name + "@" + std::to_string(options_.also_width) + "x" + std::to_string(options_.also_height));
    window_.set_size(options_.width, options_.height);
    for (int i = 0; i < 3; ++i) draw_frame();
  }

  const CaptureOptions& options_;
  WorkbenchShell& shell_;
  GlWindow& window_;
  SubjectScreen& subject_;
  std::vector<std::unique_ptr<TabCapture>>& scripts_;
  SubjectStageTrace trace_ = subject_stage_trace_from_environment();
  int status_ = 0;
  std::ofstream cut_list_;
  int cuts_ = 0;
};

}  // namespace

int run_capture(const CaptureOptions& options) {
  std::vector<std::string> ids = options.tab_ids;
  if (ids.empty()) {
    for (const auto& info : tab_registry()) ids.push_back(info.id);
  }
  if (!known_tabs(ids)) return 2;
  std::filesystem::create_directories(options.dir);
  // Before the shell: a script's scratch folders are removed after the tabs recording into them.
  std::vector<std::unique_ptr<TabCapture>> scripts;
  GlWindow window(WindowOptions{options.width, options.height, false, "LMC Workbench", options.ui_scale});
  ShellStartup startup;  // no recent-files path: a capture never touches the user's list
  startup.review = options.review;
  WorkbenchShell shell(std::move(startup));
  install_picture_renderer(shell, window);
  open_help_from_environment(shell);
  // The subject screen renders hidden at the main window's size in pixels, so its picture is
  // checked like the others.
  SubjectScreen subject(window.handle(), window.framebuffer_width(), window.framebuffer_height());
  return CaptureRun(options, shell, window, subject, scripts).run(ids);
}

}  // namespace lmc::ui
