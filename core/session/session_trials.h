#pragma once
// A subject session folder as input to processing (issue #10): the accepted attempt of each
// trial only, in plan order. Earlier attempts (under superseded/) and trials never accepted are
// left out, each with a note saying so. Read-only: processing never repairs or moves a session.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/processing/session.h"

namespace lmc::session {

// `vicon_dir` (optional) is where to look for <trial>.trc / .c3d instead of the session folder.
std::vector<TrialJob> accepted_trial_jobs(const std::filesystem::path& dir,
                                          const std::optional<std::filesystem::path>& vicon_dir,
                                          std::vector<std::string>* notes = nullptr);

}  // namespace lmc::session
