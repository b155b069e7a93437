#include "core/stats/bland_altman.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/stats/quantiles.h"

namespace lmc::bland_altman_test {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

double z975() {
  return lmc::normal_quantile(0.975);
}
double t975(double df) {
  return lmc::t_quantile(0.975, df);
}

TEST(StatsBlandAltman, HandComputedBiasLimitsAndIntervals) {
  // Differences A − B = 1, 3, 5, 7 (plus two incomplete pairs): bias 4, s² = (9+1+1+9)/3 = 20/3.
  const std::vector<double> a = {11, 13, 15, 17, kMissing, 3};
  const std::vector<double> b = {10, 10, 10, 10, 10, kMissing};
  const BlandAltmanResult r = bland_altman(a, b);
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_EQ(r.n_used, 4u);
  EXPECT_EQ(r.n_skipped, 2u);
  const double s = std::sqrt(20.0 / 3.0);
  EXPECT_DOUBLE_EQ(r.bias, 4.0);
  EXPECT_NEAR(r.sd_difference, s, 1e-12);
  EXPECT_NEAR(r.loa_low, 4.0 - z975() * s, 1e-12);
  EXPECT_NEAR(r.loa_high, 4.0 + z975() * s, 1e-12);
  EXPECT_NEAR(r.loa_low, -1.06, 0.005);  // with the papers' 1.96: 4 ∓ 1.96 · 2.582
  EXPECT_NEAR(r.loa_high, 9.06, 0.005);
  // bias CI: ± t(3) · s/√4; limit CIs: ± t(3) · sqrt(3 s²/4) = ± t(3) · √5.
  const double t = t975(3.0);
  EXPECT_NEAR(r.bias_ci.low, 4.0 - t * s / 2.0, 1e-9);
  EXPECT_NEAR(r.bias_ci.high, 4.0 + t * s / 2.0, 1e-9);
  EXPECT_NEAR(r.loa_low_ci.low, r.loa_low - t * std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(r.loa_low_ci.high, r.loa_low + t * std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(r.loa_high_ci.low, r.loa_high - t * std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(r.loa_high_ci.high, r.loa_high + t * std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(t, 3.182446, 1e-6);
  EXPECT_TRUE(std::isnan(r.within_subject_sd));  // not part of the simple form
}

TEST(StatsBlandAltman, PlotPointsAreMeanAndDifferenceOfCompletePairs) {
  const std::vector<double> a = {11, kMissing, 14};
  const std::vector<double> b = {10, 10, 10};
  const std::vector<BlandAltmanPoint> p = bland_altman_points(a, b);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0].mean, 10.5);
  EXPECT_DOUBLE_EQ(p[0].difference, 1.0);
  EXPECT_DOUBLE_EQ(p[1].mean, 12.0);
  EXPECT_DOUBLE_EQ(p[1].difference, 4.0);
}

TEST(StatsBlandAltman, FewerThanTwoPairsIsNaNWithAReason) {
  const std::vector<double> a = {1.0, kMissing};
  const std::vector<double> b = {2.0, 2.0};
  const BlandAltmanResult r = bland_altman(a, b);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.n_used, 1u);
  EXPECT_EQ(r.n_skipped, 1u);
  EXPECT_TRUE(std::isnan(r.bias));
  EXPECT_TRUE(std::isnan(r.loa_high_ci.high));
  const nlohmann::json j = nlohmann::json::parse(nlohmann::json(r).dump());
  EXPECT_TRUE(j.at("bias").is_null());
  EXPECT_TRUE(j.at("loa_low_ci").at("low").is_null());
  EXPECT_FALSE(j.at("reason").get<std::string>().empty());

  const BlandAltmanResult none = bland_altman(std::vector<double>{}, std::vector<double>{});
  EXPECT_FALSE(none.ok());
  EXPECT_TRUE(std::isnan(none.sd_difference));
}

}  // namespace lmc::bland_altman_test
