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

// Where derived results may be cached (the Review tab's processed trials): $LMC_CACHE_DIR if set,
// else $XDG_CACHE_HOME/lmc-workbench, else ~/.cache/lmc-workbench. Never inside a session folder:
// what a lab keeps and what can be thrown away stay apart. Empty when there is no home at all.
std::filesystem::path user_cache_dir();

// The study's published sample trial (reference-data/validation: Naiv_Static101 with its Vicon
// file) when it is on this machine: $LMC_REFERENCE_DATA_DIR/validation, else shared/reference-data in
// the folder that holds the source tree. Empty when absent; it is data we read, never ship.
std::filesystem::path study_sample_dir();

}  // namespace lmc
