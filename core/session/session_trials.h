#pragma once
// A subject session folder as input to processing: the accepted attempt of each
// trial only, in plan order. Earlier attempts (under superseded/) and trials never accepted are
// left out, each with a note saying so. Read-only: processing never repairs or moves a session.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/processing/batch.h"

namespace lmc {

// `vicon_dir` (optional) is where to look for <trial>.trc / .c3d instead of the session folder.
std::vector<TrialSources> accepted_trial_jobs(const std::filesystem::path& dir,
                                              const std::optional<std::filesystem::path>& vicon_dir,
                                              std::vector<std::string>* notes = nullptr);

// The trials to process for what a user opened (`lmc process INPUT`, the Review tab): a subject
// session folder gives its accepted attempts, anything else what discover_trials finds. Throws
// lmc::Error naming the input when there is nothing to process.
std::vector<TrialSources> trial_sources_for_input(const std::filesystem::path& input,
                                                  const std::optional<std::filesystem::path>& vicon,
                                                  std::vector<std::string>* notes = nullptr);

}  // namespace lmc
