#include "ui/app/capture.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>
#include <utility>

#include "ui/app/capture/text_fit_check.h"
#include "ui/app/subject_screen.h"
#include "ui/app/workbench_shell.h"
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

}  // namespace

int run_interactive(int width, int height, ShellStartup startup) {
  GlWindow window(WindowOptions{width, height, true, "LMC Workbench"});
  if (startup.recent_files_path.empty()) {
    if (const auto dir = user_config_dir(); !dir.empty()) startup.recent_files_path = dir / "recent_files.json";
  }
  WorkbenchShell shell(std::move(startup));
  install_picture_renderer(shell, window);
  SubjectScreen subject(window.handle());
  std::string title;
  while (!shell.quit_requested()) {
    if (window.should_close()) {
      window.set_should_close(false);
      shell.request_quit();
    }
    window.begin_frame();
    shell.frame();
    window.end_frame();
    window.present();
    subject.frame(shell.context().subject_screen());
    if (const std::string t = shell.window_title(); t != title) {
      title = t;
      window.set_title(title);
    }
  }
  return 0;
}

int run_capture(const CaptureOptions& options) {
  const std::string& dir = options.dir;
  const int width = options.width, height = options.height;
  std::vector<std::string> ids = options.tab_ids;
  if (ids.empty()) {
    for (const auto& info : tab_registry()) ids.push_back(info.id);
  }
  for (const auto& id : ids) {
    bool known = false;
    for (const auto& info : tab_registry()) known = known || info.id == id;
    if (!known) {
      std::cerr << "lmc-workbench: unknown tab '" << id << "' (tabs: layout, devices, record, review)\n";
      return 2;
    }
  }
  std::filesystem::create_directories(dir);
  GlWindow window(WindowOptions{width, height, false, "LMC Workbench"});
  ShellStartup startup;  // no recent-files path: a capture never touches the user's list
  startup.review = options.review;
  WorkbenchShell shell(std::move(startup));
  install_picture_renderer(shell, window);
  // LMC_CAPTURE_HELP=walkthrough|shortcuts|about (1 = walkthrough) shows the Help window over
  // every capture: menus are closed in captures, so this is the only way to look at it.
  if (const char* help = std::getenv("LMC_CAPTURE_HELP");
      help != nullptr && *help != '\0' && std::string(help) != "0") {
    const std::string which = help;
    shell.open_help(which == "shortcuts" ? HelpWindow::Section::kShortcuts
                    : which == "about"   ? HelpWindow::Section::kAbout
                                         : HelpWindow::Section::kWalkthrough);
  }
  // The subject screen renders hidden at the main window's size, so its picture is checked like
  // the others.
  SubjectScreen subject(window.handle(), width, height);
  const auto draw_frame = [&]() {
    window.begin_frame();
    shell.frame();
    window.end_frame();
    window.present();
    subject.frame(shell.context().subject_screen());
  };
  // Let the tab settle: layout needs a couple of frames; background work (a heatmap, a simulated
  // rig, a trial) gets up to 20 s to finish so the picture shows real content. While it works, a
  // frame every 100 ms: nobody watches these frames, and under Xvfb each one is drawn by the CPU
  // (Mesa's software rasteriser was 60 % of a capture's CPU time at 15 ms), which the work itself
  // and the tests beside it need.
  const auto settle = [&](Tab& tab, int settle_frames) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    int frames = 0;
    while (frames < settle_frames + 3 || (tab.busy_for_capture() && std::chrono::steady_clock::now() < deadline)) {
      draw_frame();
      ++frames;
      if (tab.busy_for_capture()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  };
  int status = 0;
  std::ofstream cut_list;
  int cuts = 0;
  const auto check_text = [&](const std::string& picture) {
    if (!options.check_text) return;
    for (const CutText& cut : find_cut_text()) {
      if (!cut_list.is_open()) cut_list.open(std::filesystem::path(dir) / "cut-text.txt");
      const std::string line = picture + ": " + describe(cut);
      cut_list << line << "\n";
      std::cerr << "lmc-workbench: text cut in " << line << "\n";
      ++cuts;
    }
  };
  const auto take_at_size = [&](const std::string& name) {
    const auto path = (std::filesystem::path(dir) / (name + ".png")).string();
    window.begin_frame();
    shell.frame();
    window.end_frame();
    const bool of_subject = name.rfind("subject-screen", 0) == 0;
    if (!of_subject) {
      window.save_png(path);
      check_text(name);
    }
    window.present();
    subject.frame(shell.context().subject_screen(), of_subject ? path : std::string());
    if (of_subject && !subject.shown()) {
      std::cerr << "lmc-workbench: the subject screen was not open (" << shell.context().subject_screen().problem
                << "), so " << path << " was not written\n";
      status = 1;
      return;
    }
    std::cout << "wrote " << path << "\n";
  };
  // The second size (a laptop's 1024 x 700) shows the same state: only the layout changes, so a
  // few frames settle it. The subject screen has its own window and size.
  const bool also = options.also_width > 0 && options.also_height > 0;
  const auto take = [&](const std::string& name) {
    take_at_size(name);
    if (!also || name.rfind("subject-screen", 0) == 0) return;
    window.set_size(options.also_width, options.also_height);
    for (int i = 0; i < 3; ++i) draw_frame();
    take_at_size(name + "@" + std::to_string(options.also_width) + "x" + std::to_string(options.also_height));
    window.set_size(width, height);
    for (int i = 0; i < 3; ++i) draw_frame();
  };
  for (const auto& id : ids) {
    size_t index = 0;
    for (size_t i = 0; i < tab_registry().size(); ++i) {
      if (tab_registry()[i].id == id) index = i;
    }
    Tab& tab = shell.tab(index);
    shell.select_tab(id);
    settle(tab, tab.prepare_for_capture());
    take(id);
    for (const auto& extra : tab.extra_captures()) {
      tab.prepare_extra_capture(extra);
      settle(tab, 2);
      take(extra);
    }
  }
  if (status == 0 && cuts > 0) {
    std::cerr << "lmc-workbench: " << cuts << " piece(s) of text not shown whole (" << dir << "/cut-text.txt)\n";
    return 3;
  }
  return status;
}

}  // namespace lmc::ui
