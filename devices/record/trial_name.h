#pragma once
// Names from outside (trial names typed by an operator, sent by Vicon, read from files) become
// file names only after this check: [A-Za-z0-9_-], 1–64 characters, not starting with '-'.
#include <filesystem>
#include <string>

#include "core/common/safe_name.h"

namespace lmc::devices {

inline constexpr size_t kMaxTrialNameLength = kMaxSafeNameLength;  // one rule: core/common/safe_name.h

// Empty when fine, else what is wrong (for the operator).
std::string validate_trial_name(const std::string& name);
// Throws lmc::Error with the message above.
void require_valid_trial_name(const std::string& name);

// True when `dir` holds any file of trial `name`: LMC_<name>.raw.txt, LMC_<name>.session.json or
// <name>.trc (sessions/README.md), i.e. when recording `name` there would overwrite something.
bool trial_files_exist(const std::filesystem::path& dir, const std::string& name);

// Recordings never overwrite: `base` when it has no file in `dir`, else the first free of
// base-2, base-3, … (base is shortened when the suffix would pass kMaxTrialNameLength). Throws
// lmc::Error when `base` is not a valid trial name.
std::string next_free_trial_name(const std::filesystem::path& dir, const std::string& base);

}  // namespace lmc::devices
