#pragma once
// Where the shipped assets (layouts, mappings, shaders) and new recordings live at run time.
#include <filesystem>

namespace lmc {

// $LMC_ASSETS_DIR if set, else `assets/` next to the executable's parent folders, else the
// source tree's assets folder baked in at build time.
std::filesystem::path assets_dir();

// assets_dir() / relative, with an Error naming the path when the file does not exist.
std::filesystem::path asset_path(const std::filesystem::path& relative);

// Where new recordings go unless the user picks another folder: $LMC_SESSIONS_DIR if set, else the
// project's `sessions/` folder (beside assets/, ignored by git), else ~/lmc-sessions for an
// installed copy whose source tree is gone.
std::filesystem::path sessions_dir();

}  // namespace lmc
