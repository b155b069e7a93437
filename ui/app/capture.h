#pragma once
// The two ways the workbench runs: interactively, or rendering tabs to PNG for review and tests.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ui/app/workbench_shell.h"

namespace lmc::ui {

// `ui_scale`: --ui-scale (ui/model/shell/ui_scale.h); unset: the screen's content scale.
int run_interactive(int width, int height, ShellStartup startup = {}, std::optional<float> ui_scale = {});
struct CaptureOptions {
  std::string dir;
  std::vector<std::string> tab_ids;  // all tabs when empty
  int width = 1280, height = 800;
  // Folders the Review tab opens first (`--review`), so its picture shows real trials.
  std::vector<std::filesystem::path> review;
  // Each picture again at this window size (DIR/<name>@WxH.png) when both are above 0.
  int also_width = 0, also_height = 0;
  // Every picture's text checked (ui/app/capture/text_fit_check.h); what is cut is listed on
  // stderr and in DIR/cut-text.txt, and the capture fails.
  bool check_text = false;
  // --ui-scale: the pictures at this scale (width × scale pixels wide); unset: the screen's.
  std::optional<float> ui_scale{};
};

// Renders each requested tab in a hidden window to DIR/<tab>.png, plus the tab's extra pictures
// (Tab::extra_captures: DIR/<name>.png); returns 0 when every PNG was written (and, when checked,
// no text is cut), 1 when one could not be written, 2 for an unknown tab name, 3 for cut text.
int run_capture(const CaptureOptions& options);

}  // namespace lmc::ui
