#pragma once
// Names from outside (trial names typed by an operator, sent by Vicon, read from files) become
// file names only after this check: [A-Za-z0-9_-], 1–64 characters, not starting with '-'.
#include <string>

namespace lmc::devices {

inline constexpr size_t kMaxTrialNameLength = 64;

// Empty when fine, else what is wrong (for the operator).
std::string validate_trial_name(const std::string& name);
// Throws lmc::Error with the message above.
void require_valid_trial_name(const std::string& name);

}  // namespace lmc::devices
