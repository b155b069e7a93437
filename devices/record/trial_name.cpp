#include "devices/record/trial_name.h"

#include <algorithm>

#include "core/common/error.h"
#include "core/common/safe_name.h"
#include "core/session/trial_files.h"

namespace lmc::devices {

std::string validate_trial_name(const std::string& name) {
  return safe_name_problem(name, "trial name");
}

void require_valid_trial_name(const std::string& name) {
  if (auto why = validate_trial_name(name); !why.empty()) throw Error("invalid trial name: " + why);
}

bool trial_files_exist(const std::filesystem::path& dir, const std::string& name) {
  // A Vicon export already copied in as <name>.trc counts too, so a new trial never pairs up with
  // another trial's ground truth.
  std::error_code ec;
  for (const auto& file : trial_files(dir, name).all())
    if (std::filesystem::exists(file, ec)) return true;
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
