#pragma once
// The two ways the workbench runs: interactively, or rendering tabs to PNG for review and tests.
#include <filesystem>
#include <string>
#include <vector>

#include "ui/app/workbench_shell.h"

namespace lmc::ui {

int run_interactive(int width, int height, ShellStartup startup = {});
// Renders each requested tab (all when empty) in a hidden window to DIR/<tab>.png, plus the
// tab's extra pictures (Tab::extra_captures: DIR/<name>.png); returns 0 when every PNG was
// written, 1 when one could not be, 2 for an unknown tab name.
// `review`: folders the Review tab opens first (`--review`), so its picture shows real trials.
int run_capture(const std::string& dir, const std::vector<std::string>& tab_ids, int width, int height,
                const std::vector<std::filesystem::path>& review = {});

}  // namespace lmc::ui
