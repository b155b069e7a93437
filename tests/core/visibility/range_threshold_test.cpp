// The batch kernel decides "out of range" by |v|² > range_sq_exact instead of sqrt(|v|²) > range
// (visibility_params.h); the two must agree on every value, ties included.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/visibility/visibility_params.h"

namespace lmc {
namespace range_threshold_test {

bool out_by_sqrt(double v2, double range) {
  return std::sqrt(v2) > range;
}

TEST(RangeThreshold, DecidesAsTheSquareRootDoesAroundTheThreshold) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(1.0, 5000.0);
  const double inf = std::numeric_limits<double>::infinity();
  for (double range : {400.0, 600.0, 0.1, 1.0, 2.0, 3.0, 1e-300, 1e150}) {
    const double t = make_limits({range, 150.0, 120.0, 10.0}).range_sq_exact;
    EXPECT_FALSE(out_by_sqrt(t, range)) << range;
    EXPECT_TRUE(out_by_sqrt(std::nextafter(t, inf), range)) << range;
    double x = t;
    for (int i = 0; i < 64; ++i) x = std::nextafter(x, -inf);
    for (int i = 0; i < 128; ++i, x = std::nextafter(x, inf)) ASSERT_EQ(x > t, out_by_sqrt(x, range)) << range;
  }
  for (int i = 0; i < 20000; ++i) {
    const double range = u(rng);
    const double t = make_limits({range, 150.0, 120.0, 10.0}).range_sq_exact;
    const double x = range * range * (1.0 + (u(rng) - 2500.0) * 1e-16);
    ASSERT_EQ(x > t, out_by_sqrt(x, range)) << range;
    ASSERT_EQ(range * range > t, out_by_sqrt(range * range, range)) << range;
  }
}

TEST(RangeThreshold, ZeroAndNonFiniteRanges) {
  EXPECT_EQ(make_limits({0.0, 150.0, 120.0, 10.0}).range_sq_exact, 0.0);
  EXPECT_EQ(make_limits({std::numeric_limits<double>::infinity(), 150.0, 120.0, 10.0}).range_sq_exact,
            std::numeric_limits<double>::infinity());
}

}  // namespace range_threshold_test
}  // namespace lmc
