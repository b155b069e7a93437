// Which controllers of a layout cannot see the hand at all: the paper's table puts LMC1 at
// z = +256.29, looking away from the hand (the authors' processing used −256.29).
#include <gtest/gtest.h>

#include "core/io/layout_json.h"
#include "core/visibility/blind_controllers.h"

namespace lmc {
namespace {

TEST(BlindControllers, ThePapersTableLeavesLmc1LookingAwayFromTheHand) {
  const std::vector<BlindController> blind = blind_controllers(load_layout_or_preset("paper-optimized"));
  ASSERT_EQ(blind.size(), 1u);
  EXPECT_EQ(blind[0].device, 0);
  EXPECT_EQ(blind[0].slot, "LMC1");
  EXPECT_EQ(blind[0].reason, HiddenReason::kOutOfView);
}

// The preset keeps the table's numbers and says what is wrong with them where the workbench shows it.
TEST(BlindControllers, ThePapersTablePresetSaysWhatIsWrongWithIt) {
  const std::string d = load_layout_or_preset("paper-optimized").description;
  EXPECT_NE(d.find("LMC1 at z = +256.29 looks away from the hand"), std::string::npos) << d;
  EXPECT_NE(d.find("z = -256.29 (preset paper-optimized-as-processed"), std::string::npos) << d;
}

TEST(BlindControllers, EveryControllerOfTheProcessedAndTheInitialLayoutSeesTheHand) {
  EXPECT_TRUE(blind_controllers(load_layout_or_preset("paper-optimized-as-processed")).empty());
  EXPECT_TRUE(blind_controllers(load_layout_or_preset("paper-initial")).empty());
}

TEST(BlindControllers, AControllerBeyondItsRangeIsNamedWithThatReason) {
  Layout l = load_layout_or_preset("paper-optimized-as-processed");
  l.devices[2].pose.x_mm = -900.0;  // LMC3 on the table, 0.9 m to the side: beyond the 600 mm range
  l.devices[2].pose.ry_deg = 0.0;
  const std::vector<BlindController> blind = blind_controllers(l);
  ASSERT_EQ(blind.size(), 1u);
  EXPECT_EQ(blind[0].device, 2);
  EXPECT_EQ(blind[0].slot, "LMC3");
  EXPECT_EQ(blind[0].reason, HiddenReason::kOutOfRange);
}

}  // namespace
}  // namespace lmc
