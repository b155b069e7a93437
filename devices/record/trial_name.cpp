#include "devices/record/trial_name.h"

#include <algorithm>

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

bool trial_files_exist(const std::filesystem::path& dir, const std::string& name) {
  // The same three names as session_paths (recorder.h); a Vicon export already copied in as
  // <name>.trc counts too, so a new trial never pairs up with another trial's ground truth.
  std::error_code ec;
  for (const std::string& file : {"LMC_" + name + ".raw.txt", "LMC_" + name + ".session.json", name + ".trc"})
    if (std::filesystem::exists(dir / file, ec)) return true;
  return false;
}

std::string next_free_trial_name(const std::filesystem::path& dir, const std::string& base) {
  require_valid_trial_name(base);
  if (!trial_files_exist(dir, base)) return base;
  for (int n = 2;; ++n) {
    const std::string suffix = "-" + std::to_string(n);
    const std::string name = base.substr(0, std::min(base.size(), kMaxTrialNameLength - suffix.size())) + suffix;
    if (!trial_files_exist(dir, name)) return name;
  }
}

}  // namespace lmc::devices
