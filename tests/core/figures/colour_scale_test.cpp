// The heatmaps' sequential scale: viridis' ends, clamped outside [0, 1], and lighter as the value
// grows, so the order reads in greyscale and for readers with colour-vision deficiencies too.
#include "core/figures/colour_scale.h"

#include <gtest/gtest.h>

#include <limits>

namespace lmc::colour_scale_test {

double luma(Rgb c) {
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

TEST(FiguresColourScale, RunsFromViridisDarkEndToItsBrightEnd) {
  EXPECT_EQ(sequential_colour(0.0), (Rgb{68, 1, 84}));
  EXPECT_EQ(sequential_colour(1.0), (Rgb{253, 231, 37}));
  EXPECT_EQ(sequential_colour(-3.0), sequential_colour(0.0));
  EXPECT_EQ(sequential_colour(7.0), sequential_colour(1.0));
  EXPECT_EQ(sequential_colour(std::numeric_limits<double>::quiet_NaN()), sequential_colour(0.0));
}

TEST(FiguresColourScale, GetsLighterAsTheValueGrows) {
  double previous = -1;
  for (int i = 0; i <= 100; ++i) {
    const double l = luma(sequential_colour(i / 100.0));
    EXPECT_GT(l, previous) << i;
    previous = l;
  }
  EXPECT_TRUE(wants_light_text(sequential_colour(0.2)));
  EXPECT_FALSE(wants_light_text(sequential_colour(0.8)));
}

}  // namespace lmc::colour_scale_test
