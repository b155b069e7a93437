#pragma once
// A subject session of the `quick` protocol recorded on the simulated rig in simulated time, made
// with the `lmc` command as a lab would: what the Review tab's and the review model's tests open,
// and what the figures and export commands' tests read.
#include <filesystem>
#include <string>

#include "tests/support/cli_runner.h"

namespace lmc::test {

// Creates and records the session folder `session` of `subject` with the simulator's `seed`, the
// commands' output under `logs`. Returns "" when both commands succeeded, else what they printed.
inline std::string record_quick_session(const std::filesystem::path& session, const std::filesystem::path& logs,
                                        const std::string& subject = "S01", int seed = 6) {
  const std::string folder = shell_quote(session.string());
  CliRun r = run_lmc("session new --subject " + subject + " --protocol quick -o " + folder, logs / "new");
  if (r.exit_code != 0) return r.all();
  r = run_lmc("session run " + folder + " --backend sim --fast --auto --seed " + std::to_string(seed) + " --quiet",
              logs / "run");
  return r.exit_code == 0 ? "" : r.all();
}

}  // namespace lmc::test
