#pragma once
// Where the workbench keeps what belongs to the user rather than the repository (ImGui's window
// layout, the recent-files list): $XDG_CONFIG_HOME/lmc-workbench, else ~/.config/lmc-workbench.
#include <filesystem>

namespace lmc::ui {

// Creates the folder when missing; empty when there is no home or it cannot be created (the
// caller then keeps nothing between runs).
std::filesystem::path user_config_dir();

}  // namespace lmc::ui
