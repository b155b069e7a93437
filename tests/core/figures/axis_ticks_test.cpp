#include "core/figures/axis_ticks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace lmc::axis_ticks_test {

// True when v is 1, 2 or 5 times a power of ten.
bool is_round_step(double v) {
  const double p = std::pow(10.0, std::floor(std::log10(v) + 1e-12));
  const double m = v / p;
  for (const double r : {1.0, 2.0, 5.0, 10.0})
    if (std::abs(m - r) < 1e-9) return true;
  return false;
}

TEST(FiguresAxisTicks, TicksAreRoundMultiplesOfARoundStepInsideTheRange) {
  for (const auto& [lo, hi] : {std::pair{0.0, 1.0},
                               {-3.2, 7.9},
                               {0.013, 0.049},
                               {1234.0, 98765.0},
                               {-0.002, 0.0031},
                               {17.0, 18.0},
                               {-1e6, -2e5}}) {
    for (int target : {2, 4, 5, 8}) {
      const auto t = nice_ticks(lo, hi, target);
      ASSERT_GE(t.size(), 2u) << lo << " " << hi << " " << target;
      const double step = t[1] - t[0];
      EXPECT_TRUE(is_round_step(step)) << step;
      for (size_t i = 0; i < t.size(); ++i) {
        EXPECT_GE(t[i], lo - step * 1e-6);
        EXPECT_LE(t[i], hi + step * 1e-6);
        const double k = t[i] / step;
        EXPECT_NEAR(k, std::round(k), 1e-6) << t[i];
        if (i > 0) {
          EXPECT_NEAR(t[i] - t[i - 1], step, step * 1e-6);
        }
      }
    }
  }
}

TEST(FiguresAxisTicks, ZeroIsExactlyZeroAndAnEmptyRangeHasNoTicks) {
  const auto t = nice_ticks(-0.3, 0.3, 6);
  bool zero = false;
  for (const double v : t) zero = zero || (v == 0.0 && !std::signbit(v));
  EXPECT_TRUE(zero);
  EXPECT_TRUE(nice_ticks(2, 2, 5).empty());
  EXPECT_TRUE(nice_ticks(std::nan(""), 1, 5).empty());
}

TEST(FiguresAxisTicks, LabelsHaveJustEnoughDecimalsForTheirStep) {
  EXPECT_EQ(tick_label(40, {0, 20, 40}), "40");
  EXPECT_EQ(tick_label(0.4, {0, 0.2, 0.4}), "0.4");  // nice_ticks steps are 1, 2 or 5 × 10^k
  EXPECT_EQ(tick_label(0.05, {0, 0.05, 0.1}), "0.05");
  EXPECT_EQ(tick_label(1.5, {1, 1.5, 2}), "1.5");
  EXPECT_EQ(tick_label(-0.002, {-0.004, -0.002, 0}), "-0.002");
  EXPECT_EQ(tick_label(7, {7}), "7");  // a single tick: whole numbers
}

// The Review plots' cursor readout: Vicon's index DIP angle of 8.5e-07° on a 0–12° axis was shown
// as "8.5e-07"; read off the axis it is 0.0.
TEST(FiguresAxisTicks, AValueReadOffAnAxisHasTheAxissResolution) {
  EXPECT_EQ(value_label(8.5e-07, 0, 12), "0.0");
  EXPECT_EQ(value_label(-8.5e-07, 0, 12), "0.0");  // no sign on a rounded zero
  EXPECT_EQ(value_label(9.4996, 0, 12), "9.5");
  EXPECT_EQ(value_label(87.134, 86, 88.5), "87.13");
  EXPECT_EQ(value_label(0.86331, 0.8, 1.3), "0.863");
  EXPECT_EQ(value_label(153.26, 0, 180), "153");
  EXPECT_EQ(value_label(1234.6, 0, 5000), "1235");  // whole numbers from a span of 100 up
  EXPECT_EQ(value_label(0.5, 1, 1), "0.50");        // an empty span: two decimals
  EXPECT_EQ(value_label(0.5, 0, std::nan("")), "0.50");
}

}  // namespace lmc::axis_ticks_test
