#include "core/session/trial_files.h"

namespace lmc {

TrialFiles trial_files(const std::filesystem::path& dir, const std::string& trial) {
  return {dir / ("LMC_" + trial + ".raw.txt"), dir / ("LMC_" + trial + ".session.json"), dir / (trial + ".trc")};
}

}  // namespace lmc
