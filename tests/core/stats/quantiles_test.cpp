#include "core/stats/quantiles.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lmc::quantiles_test {

// Values from printed tables (to the digits shown): the wrappers must hand Boost the right
// arguments.
TEST(StatsQuantiles, MatchPrintedTables) {
  EXPECT_NEAR(normal_quantile(0.975), 1.959964, 1e-6);
  EXPECT_NEAR(t_quantile(0.975, 9.0), 2.262157, 1e-6);
  EXPECT_NEAR(t_quantile(0.025, 9.0), -2.262157, 1e-6);
  EXPECT_NEAR(f_quantile(0.95, 5.0, 15.0), 2.901295, 1e-6);
  EXPECT_NEAR(chi_squared_quantile(0.975, 3.0), 9.348404, 1e-6);
  EXPECT_NEAR(chi_squared_quantile(0.025, 3.0), 0.2157953, 1e-6);
  EXPECT_NEAR(f_upper_tail(2.901295, 5.0, 15.0), 0.05, 1e-6);
}

TEST(StatsQuantiles, InvalidArgumentsGiveNaNNotExceptions) {
  EXPECT_TRUE(std::isnan(normal_quantile(0.0)));
  EXPECT_TRUE(std::isnan(normal_quantile(1.0)));
  EXPECT_TRUE(std::isnan(t_quantile(0.975, 0.0)));
  EXPECT_TRUE(std::isnan(t_quantile(std::nan(""), 5.0)));
  EXPECT_TRUE(std::isnan(f_quantile(0.975, 5.0, -1.0)));
  EXPECT_TRUE(std::isnan(chi_squared_quantile(0.5, std::nan(""))));
  EXPECT_TRUE(std::isnan(f_upper_tail(std::nan(""), 1.0, 1.0)));
}

}  // namespace lmc::quantiles_test
