#include "devices/record/trial_name.h"

#include "core/common/error.h"

namespace lmc::devices {

std::string validate_trial_name(const std::string& name) {
  if (name.empty()) return "trial name is empty";
  if (name.size() > kMaxTrialNameLength)
    return "trial name is longer than " + std::to_string(kMaxTrialNameLength) + " characters";
  if (name.front() == '-') return "trial name must not start with '-'";
  for (size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    if (!ok)
      return "trial name has a character other than letters, digits, '_' or '-' at position " + std::to_string(i + 1);
  }
  return {};
}

void require_valid_trial_name(const std::string& name) {
  if (auto why = validate_trial_name(name); !why.empty()) throw Error("invalid trial name: " + why);
}

}  // namespace lmc::devices
