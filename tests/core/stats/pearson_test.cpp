#include "core/stats/pearson.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/stats/quantiles.h"

namespace lmc::pearson_test {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

TEST(StatsPearson, HandComputedValueAndFisherInterval) {
  // Deviations a: −2 −1 0 1 2, b: −2 0 1 0 1 → Sab = 6, Saa = 10, Sbb = 6, r = 6/√60.
  const std::vector<double> a = {1, 2, 3, 4, 5, kMissing};
  const std::vector<double> b = {2, 4, 5, 4, 5, 7};
  const PearsonResult p = pearson(a, b);
  EXPECT_TRUE(p.ok()) << p.reason;
  EXPECT_EQ(p.n_used, 5u);
  EXPECT_EQ(p.n_skipped, 1u);
  const double r = 6.0 / std::sqrt(60.0);
  EXPECT_NEAR(p.r, r, 1e-12);
  const double z = lmc::normal_quantile(0.975);
  const double half = z / std::sqrt(5.0 - 3.0);
  EXPECT_NEAR(p.ci.low, std::tanh(std::atanh(r) - half), 1e-9);
  EXPECT_NEAR(p.ci.high, std::tanh(std::atanh(r) + half), 1e-9);
  // By hand: atanh(r) = 1.03172, half = 1.38590 → tanh(−0.35418) = −0.3401, tanh(2.41762) = 0.9843.
  EXPECT_NEAR(p.ci.low, -0.3401, 1e-4);
  EXPECT_NEAR(p.ci.high, 0.9843, 1e-4);
}

TEST(StatsPearson, PerfectCorrelationHasADegenerateInterval) {
  const std::vector<double> a = {1, 2, 3, 4, 5};
  const std::vector<double> b = {3, 5, 7, 9, 11};
  const PearsonResult p = pearson(a, b);
  EXPECT_DOUBLE_EQ(p.r, 1.0);
  EXPECT_DOUBLE_EQ(p.ci.low, 1.0);
  EXPECT_DOUBLE_EQ(p.ci.high, 1.0);
}

TEST(StatsPearson, TooFewPairsOrNoSpreadIsNaNWithAReason) {
  const std::vector<double> two_a = {1, 2, kMissing};
  const std::vector<double> two_b = {1, 3, 4};
  const PearsonResult two = pearson(two_a, two_b);
  EXPECT_TRUE(std::isnan(two.r));
  EXPECT_FALSE(two.reason.empty());

  const std::vector<double> three_a = {1, 2, 3};
  const std::vector<double> three_b = {1, 3, 2};
  const PearsonResult three = pearson(three_a, three_b);
  EXPECT_DOUBLE_EQ(three.r, 0.5);
  EXPECT_TRUE(std::isnan(three.ci.low));
  EXPECT_FALSE(three.reason.empty());

  const std::vector<double> flat = {2, 2, 2, 2};
  const std::vector<double> other = {1, 2, 3, 4};
  const PearsonResult constant = pearson(flat, other);
  EXPECT_TRUE(std::isnan(constant.r));
  EXPECT_FALSE(constant.reason.empty());
  const nlohmann::json j = nlohmann::json::parse(nlohmann::json(constant).dump());
  EXPECT_TRUE(j.at("r").is_null());
}

}  // namespace lmc::pearson_test
