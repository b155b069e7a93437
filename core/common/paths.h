#pragma once
// Where the shipped assets (layouts, mappings, shaders) and new recordings live at run time.
#include <filesystem>

namespace lmc {

// $LMC_ASSETS_DIR if set, else `assets/` next to the executable's parent folders, else the
// source tree's assets folder baked in at build time.
std::filesystem::path assets_dir();

// assets_dir() / relative, with an Error naming the path when the file does not exist.
std::filesystem::path asset_path(const std::filesystem::path& relative);

// The user's own data folder for the workbench: $XDG_DATA_HOME/lmc-workbench, else
// ~/.local/share/lmc-workbench (Documents\lmc-workbench on Windows). Outside the program's folder,
// so a `git clean`, an update or a second clone neither loses nor splits a lab's recordings.
// Empty when there is no home at all.
std::filesystem::path user_data_dir();

// Where new recordings, exports and test recordings go unless the user picks another folder:
// $LMC_SESSIONS_DIR if set, else user_data_dir(), else (no home) the project's `sessions/` folder.
std::filesystem::path sessions_dir();

// The demo sessions `scripts/run` records: $LMC_SESSIONS_DIR/demo when set, else the project's
// sessions/demo (beside assets/) when it is there, else sessions_dir()/demo.
std::filesystem::path demo_sessions_dir();

// Where derived results may be cached (the Review tab's processed trials): $LMC_CACHE_DIR if set,
// else $XDG_CACHE_HOME/lmc-workbench, else ~/.cache/lmc-workbench. Never inside a session folder:
// what a lab keeps and what can be thrown away stay apart. Empty when there is no home at all.
std::filesystem::path user_cache_dir();

// The study's published sample trial (reference-data/validation: Naiv_Static101 with its Vicon
// file) when it is on this machine: $LMC_REFERENCE_DATA_DIR/validation, else shared/reference-data in
// the folder that holds the source tree. Empty when absent; it is data we read, never ship.
std::filesystem::path study_sample_dir();

}  // namespace lmc
