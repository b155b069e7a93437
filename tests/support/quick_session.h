#pragma once
// A subject session of the `quick` protocol recorded on the simulated rig in simulated time, made
// with the `lmc` command as a lab would: what the Review tab's and the review model's tests open,
// and what the figures and export commands' tests read.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/cli_runner.h"
#include "tests/support/scratch_dir.h"

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

// A GoogleTest suite that shares one quick session, recorded before its first test (about two
// seconds) and removed after its last. The suite's fixture derives from
// QuickSessionSuite<itself> and names its scratch folder (`kScratchName`) and the simulator's
// seed (`kSeed`); its tests read root() and session().
template <class Suite>
class QuickSessionSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new std::filesystem::path(scratch_dir(Suite::kScratchName));
    session_ = new std::filesystem::path(*root_ / "S01");
    ASSERT_EQ(record_quick_session(*session_, *root_ / "logs", "S01", Suite::kSeed), "");
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*root_);
    delete session_;
    delete root_;
    session_ = root_ = nullptr;
  }
  static const std::filesystem::path& root() { return *root_; }
  static const std::filesystem::path& session() { return *session_; }

 private:
  static inline std::filesystem::path* root_ = nullptr;
  static inline std::filesystem::path* session_ = nullptr;
};

}  // namespace lmc::test
