// lmc-workbench — the desktop workbench. `--capture DIR [--tab NAME]` renders tabs to PNG and exits.
#include <CLI/CLI.hpp>
#include <csignal>
#include <filesystem>
#include <iostream>

#include "ui/app/capture.h"
#include "ui/app/workbench_shell.h"
#include "ui/platform/gl_window.h"

int main(int argc, char** argv) {
#ifdef SIGXFSZ
  // A file-size limit (ulimit -f) must not kill the workbench while it records: ignored, the
  // write fails with EFBIG and the recorder stops the trial with a clear message instead.
  std::signal(SIGXFSZ, SIG_IGN);
#endif
  CLI::App app{"LMC Workbench — design controller layouts, record trials and review results."};
  app.set_version_flag("--version", std::string("lmc-workbench ") + LMC_VERSION);
  std::string capture_dir;
  std::vector<std::string> capture_tabs;
  int width = 1280, height = 800;
  app.add_option("--capture", capture_dir, "Render tabs to PNG files in this folder, then exit");
  app.add_option("--tab", capture_tabs, "With --capture: which tabs (layout, devices, record, review); default all");
  app.add_option("--size", width, "Window width in pixels")->check(CLI::Range(640, 7680));
  app.add_option("--height", height, "Window height in pixels")->check(CLI::Range(480, 4320));
  CLI11_PARSE(app, argc, argv);

  try {
    if (!capture_dir.empty()) {
      return lmc::ui::run_capture(capture_dir, capture_tabs, width, height);
    }
    return lmc::ui::run_interactive(width, height);
  } catch (const std::exception& e) {
    std::cerr << "lmc-workbench: " << e.what() << "\n";
    return 1;
  }
}
