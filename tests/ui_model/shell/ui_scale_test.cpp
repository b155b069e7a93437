// The one rule for a high-DPI screen: the content scale (or --ui-scale) → the font's pixel size and
// the factor between ImGui units and window pixels.
#include <gtest/gtest.h>

#include <limits>

#include "ui/model/shell/ui_scale.h"

namespace lmc::ui {
namespace ui_scale_test {  // named: test files share unity batches

TEST(UiScale, A150PercentScreenDrawsTextAndSizesOneAndAHalfTimesLarger) {
  const UiScale s = choose_ui_scale(1.5F);
  EXPECT_FLOAT_EQ(s.scale, 1.5F);
  EXPECT_FLOAT_EQ(s.font_px, 19.5F);
  EXPECT_EQ(scaled_pixels(1280, s), 1920);
  EXPECT_EQ(scaled_pixels(800, s), 1200);
}

TEST(UiScale, AnOrdinaryScreenKeepsTheBuiltInFontAtThirteenPixels) {
  EXPECT_EQ(choose_ui_scale(1.0F), (UiScale{1.0F, 13.0F}));
  EXPECT_EQ(scaled_pixels(1280, choose_ui_scale(1.0F)), 1280);
}

TEST(UiScale, RoundsToAQuarterSoANearlyOrdinaryScreenDoesNotBlurTheFont) {
  EXPECT_FLOAT_EQ(choose_ui_scale(97.0F / 96.0F).scale, 1.0F);    // 97 dpi
  EXPECT_FLOAT_EQ(choose_ui_scale(120.0F / 96.0F).scale, 1.25F);  // 125 %
  EXPECT_FLOAT_EQ(choose_ui_scale(1.74F).scale, 1.75F);
  EXPECT_FLOAT_EQ(choose_ui_scale(2.0F).font_px, 26.0F);
}

TEST(UiScale, KeepsWithinOneToThreeAndTreatsNonsenseAsOne) {
  EXPECT_FLOAT_EQ(choose_ui_scale(0.75F).scale, 1.0F);  // smaller would cut the layouts' text
  EXPECT_FLOAT_EQ(choose_ui_scale(5.0F).scale, 3.0F);
  EXPECT_FLOAT_EQ(choose_ui_scale(0.0F).scale, 1.0F);  // GLFW's answer when it could not ask
  EXPECT_FLOAT_EQ(choose_ui_scale(-2.0F).scale, 1.0F);
  EXPECT_FLOAT_EQ(choose_ui_scale(std::numeric_limits<float>::quiet_NaN()).scale, 1.0F);
}

TEST(UiScale, TheOperatorsOverrideWinsOverTheScreen) {
  EXPECT_FLOAT_EQ(choose_ui_scale(1.0F, 1.5F).scale, 1.5F);
  EXPECT_FLOAT_EQ(choose_ui_scale(2.0F, 1.0F).scale, 1.0F);
  EXPECT_FLOAT_EQ(choose_ui_scale(1.5F, std::nullopt).scale, 1.5F);
}

TEST(UiScale, ParsesTheOptionAsANumberAPercentageOrAuto) {
  std::optional<float> s;
  std::string error;
  ASSERT_TRUE(parse_ui_scale("1.5", s, error));
  EXPECT_FLOAT_EQ(*s, 1.5F);
  ASSERT_TRUE(parse_ui_scale("125%", s, error));
  EXPECT_FLOAT_EQ(*s, 1.25F);
  ASSERT_TRUE(parse_ui_scale("auto", s, error));
  EXPECT_FALSE(s.has_value());
  for (const char* bad : {"big", "0.5", "4", "1.5x", "%", "nan"}) {
    error.clear();
    EXPECT_FALSE(parse_ui_scale(bad, s, error)) << bad;
    EXPECT_NE(error.find("--ui-scale"), std::string::npos) << bad;
  }
}

}  // namespace ui_scale_test
}  // namespace lmc::ui
