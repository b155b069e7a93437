// lmc-workbench — the desktop workbench. `--capture DIR [--tab NAME]` renders tabs to PNG and exits.
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <utility>

#include "core/platform/command_line.h"
#include "core/visibility/visibility_kernel.h"
#include "devices/leapc/leapc_library.h"
#include "ui/app/capture.h"
#include "ui/app/workbench_shell.h"
#include "ui/model/shell/ui_scale.h"
#include "ui/platform/gl_window.h"

int main(int argc, char** argv) {
  if (const std::string problem = lmc::platform::arguments_changed_by_code_page(); !problem.empty()) {
    std::cerr << "lmc-workbench: " << problem << "\n";
    return 2;
  }
#ifdef SIGXFSZ
  // A file-size limit (ulimit -f) must not kill the workbench while it records: ignored, the
  // write fails with EFBIG and the recorder stops the trial with a clear message instead.
  std::signal(SIGXFSZ, SIG_IGN);
#endif
  CLI::App app{"LMC Workbench — design controller layouts, record trials and review results."};
  app.set_version_flag("--version", std::string("lmc-workbench ") + LMC_VERSION);
  app.allow_windows_style_options(false);  // as in lmc: a /path is a path, not an option
  std::string capture_dir;
  std::vector<std::string> capture_tabs;
  int width = 1280, height = 800;
  app.add_option("--capture", capture_dir, "Render tabs to PNG files in this folder, then exit");
  app.add_option(
      "--tab", capture_tabs,
      "With --capture: which tabs (layout, devices, record, review); default all. Otherwise the tab shown first");
  std::string session, backend = "sim";
  bool fast = false;
  app.add_option("--session", session, "Open (resume) this subject session folder in the Record tab");
  app.add_option("--backend", backend, "With --session: sim or leapc")->check(CLI::IsMember({"sim", "leapc"}));
  app.add_flag("--fast", fast, "With --session and the simulated rig: simulated time (demos, tests)");
  std::string subject_screen;
  CLI::Option* subject_screen_opt =
      app.add_option("--subject-screen", subject_screen,
                     "Open the Record tab's subject screen at start-up: on monitor MONITOR (0 = the primary; default "
                     "the last one) or, with 'window', as a plain window (one-monitor bench)")
          ->expected(0, 1);
  std::vector<std::string> review;
  app.add_option(
      "--review", review,
      "Open these folders (subject sessions, folders of trials) in the Review tab at start-up; with --capture, "
      "its picture shows them");
  std::string leapc_library;
  app.add_option("--leapc-library", leapc_library,
                 "The LeapC library to load (else LMC_LEAPC_LIBRARY, else where Ultraleap installs it)");
  std::string also_size;
  bool check_text = false;
  app.add_option("--also-size", also_size,
                 "With --capture: every picture again at this window size, WxH (NAME@WxH.png)")
      ->check([](const std::string& v) {
        int w = 0, h = 0;
        char x = 0;
        return std::sscanf(v.c_str(), "%d%c%d", &w, &x, &h) == 3 && x == 'x' && w >= 640 && h >= 480
                   ? std::string()
                   : std::string("expected WxH, at least 640x480");
      });
  app.add_flag("--check-text", check_text,
               "With --capture: fail (exit 3) when a picture shows text cut by its window or its widget, shortened "
               "with an ellipsis, or drawn over other text; the list in DIR/cut-text.txt");
  app.add_option("--size", width, "Window width (in pixels at a UI scale of 1)")->check(CLI::Range(640, 7680));
  app.add_option("--height", height, "Window height (in pixels at a UI scale of 1)")->check(CLI::Range(480, 4320));
  std::string ui_scale_text;
  app.add_option("--ui-scale", ui_scale_text,
                 "Text and controls this many times larger: 1.5 or 150% (default auto: the screen's scaling)");
  CLI11_PARSE(app, argc, argv);
  std::optional<float> ui_scale;
  if (std::string error; !lmc::ui::parse_ui_scale(ui_scale_text, ui_scale, error)) {
    std::cerr << "lmc-workbench: " << error << "\n";
    return 2;
  }
  if (!leapc_library.empty()) lmc::devices::set_leapc_library_path(leapc_library);
  // An unknown LMC_KERNEL leaves the fastest kernel build running; say so rather than ignore it.
  if (const std::string problem = lmc::kernel_setting_problem(); !problem.empty()) {
    std::cerr << "lmc-workbench: " << problem << "\n";
  }

  try {
    if (!capture_dir.empty()) {
      lmc::ui::CaptureOptions capture{capture_dir, capture_tabs, width, height, {review.begin(), review.end()}};
      if (!also_size.empty()) std::sscanf(also_size.c_str(), "%dx%d", &capture.also_width, &capture.also_height);
      capture.check_text = check_text;
      capture.ui_scale = ui_scale;
      return lmc::ui::run_capture(capture);
    }
    lmc::ui::ShellStartup startup;
    if (subject_screen_opt->count() > 0) {
      std::string error;
      startup.subject_screen = lmc::ui::parse_subject_screen_arg(subject_screen, error);
      if (!startup.subject_screen) {
        std::cerr << "lmc-workbench: " << error << "\n";
        return 2;
      }
    }
    if (!capture_tabs.empty()) startup.tab = capture_tabs.front();
    startup.review.assign(review.begin(), review.end());
    if (!review.empty() && startup.tab.empty()) startup.tab = "review";
    if (!session.empty()) {
      startup.record = lmc::ui::RecordStartup{session, backend, fast};
      if (startup.tab.empty()) startup.tab = "record";
    }
    return lmc::ui::run_interactive(width, height, std::move(startup), ui_scale);
  } catch (const std::exception& e) {
    std::cerr << "lmc-workbench: " << e.what() << "\n";
    return 1;
  }
}
