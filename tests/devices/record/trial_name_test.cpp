// Never-overwrite trial names (devices/record/trial_name.h): every caller of the trial engine
// picks the next free name this way.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "devices/record/trial_name.h"
#include "tests/support/reference_data.h"

namespace lmc::devices {
namespace {

TEST(TrialName, NextFreeNameSkipsEveryTakenFileKind) {
  const auto dir = test::scratch_dir("next_free_trial_name");
  EXPECT_EQ(next_free_trial_name(dir, "T"), "T");
  std::ofstream(dir / "LMC_T.raw.txt") << "x";
  EXPECT_EQ(next_free_trial_name(dir, "T"), "T-2");
  std::ofstream(dir / "LMC_T-2.session.json") << "x";
  std::ofstream(dir / "T-3.trc") << "x";
  EXPECT_EQ(next_free_trial_name(dir, "T"), "T-4");
  EXPECT_TRUE(trial_files_exist(dir, "T-3"));
  EXPECT_FALSE(trial_files_exist(dir, "T-4"));
  // A name at the length limit is shortened so that its suffix fits.
  const std::string longest(kMaxTrialNameLength, 'a');
  std::ofstream(dir / ("LMC_" + longest + ".raw.txt")) << "x";
  const std::string next = next_free_trial_name(dir, longest);
  EXPECT_EQ(next, std::string(kMaxTrialNameLength - 2, 'a') + "-2");
  EXPECT_EQ(validate_trial_name(next), "");
  EXPECT_THROW(next_free_trial_name(dir, "../x"), Error);
}

}  // namespace
}  // namespace lmc::devices
