#pragma once
// Shows a folder in the desktop's file manager (a finished export's "Open folder"). The opener runs
// detached: the workbench never waits for it, and it outlives no zombie.
#include <filesystem>
#include <string>

namespace lmc::ui {

// Starts `program FOLDER` (xdg-open by default: the desktop's choice of file manager) and returns
// at once. False, with the reason in `error`, when the folder does not exist or the program could
// not be started; the program's own failure to open it is not seen.
bool open_in_file_manager(const std::filesystem::path& folder, std::string* error = nullptr,
                          const std::string& program = "xdg-open");

}  // namespace lmc::ui
