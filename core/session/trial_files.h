#pragma once
// The files one recorded trial leaves in a folder (sessions/README.md): the recorder's raw file
// and sidecar and the ground truth / Vicon TRC, all named after the trial so LMC and Vicon files
// pair by name. The recorder, the session folder (which moves earlier attempts aside) and
// processing all take the names from here.
#include <array>
#include <filesystem>
#include <string>

namespace lmc {

struct TrialFiles {
  std::filesystem::path recording;  // <dir>/LMC_<trial>.raw.txt
  std::filesystem::path sidecar;    // <dir>/LMC_<trial>.session.json
  std::filesystem::path truth_trc;  // <dir>/<trial>.trc (simulator ground truth / Vicon export)
  std::array<std::filesystem::path, 3> all() const { return {recording, sidecar, truth_trc}; }
};

TrialFiles trial_files(const std::filesystem::path& dir, const std::string& trial);

}  // namespace lmc
