#include "core/stats/descriptives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/common/error.h"

namespace lmc::descriptives_test {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

TEST(StatsDescriptives, SkipsMissingValuesAndCountsThem) {
  const std::vector<double> v = {2.0, 4.0, kMissing, std::numeric_limits<double>::infinity(), 6.0};
  const Descriptives d = describe(v);
  EXPECT_TRUE(d.ok());
  EXPECT_EQ(d.n_used, 3u);
  EXPECT_EQ(d.n_skipped, 2u);
  EXPECT_DOUBLE_EQ(d.mean, 4.0);
  EXPECT_DOUBLE_EQ(d.sd, 2.0);
}

TEST(StatsDescriptives, PairsWithAMissingSideAreSkippedWhole) {
  // Complete pairs (1,1), (3,2), (4,2): differences 0, 1, 2.
  const std::vector<double> a = {1.0, 2.0, 3.0, 4.0, kMissing};
  const std::vector<double> b = {1.0, kMissing, 2.0, 2.0, 5.0};
  const PairedDescriptives d = describe_pairs(a, b);
  EXPECT_TRUE(d.ok());
  EXPECT_EQ(d.n_used, 3u);
  EXPECT_EQ(d.n_skipped, 2u);
  EXPECT_DOUBLE_EQ(d.mean_difference, 1.0);
  EXPECT_DOUBLE_EQ(d.sd_difference, 1.0);
  EXPECT_DOUBLE_EQ(d.mean_abs_difference, 1.0);
  EXPECT_DOUBLE_EQ(d.rmse, std::sqrt(5.0 / 3.0));
  EXPECT_DOUBLE_EQ(d.mean_a, 8.0 / 3.0);
  EXPECT_DOUBLE_EQ(d.sd_a, std::sqrt(7.0 / 3.0));
  EXPECT_DOUBLE_EQ(d.mean_b, 5.0 / 3.0);
  EXPECT_DOUBLE_EQ(d.sd_b, std::sqrt(1.0 / 3.0));
}

TEST(StatsDescriptives, FewerThanTwoPairsIsNaNWithAReason) {
  const std::vector<double> a = {1.0, kMissing, 3.0};
  const std::vector<double> b = {2.0, 3.0, kMissing};
  const PairedDescriptives d = describe_pairs(a, b);
  EXPECT_FALSE(d.ok());
  EXPECT_FALSE(d.reason.empty());
  EXPECT_EQ(d.n_used, 1u);
  EXPECT_EQ(d.n_skipped, 2u);
  EXPECT_TRUE(std::isnan(d.mean_difference));
  EXPECT_TRUE(std::isnan(d.rmse));
  EXPECT_TRUE(std::isnan(d.mean_a));

  const Descriptives empty = describe(std::vector<double>{});
  EXPECT_FALSE(empty.ok());
  EXPECT_TRUE(std::isnan(empty.mean));
}

TEST(StatsDescriptives, UnequalLengthsAreAnError) {
  const std::vector<double> a = {1.0, 2.0};
  const std::vector<double> b = {1.0};
  EXPECT_THROW(describe_pairs(a, b), lmc::Error);
}

TEST(StatsDescriptives, JsonWritesNaNAsNullNeverZero) {
  const std::vector<double> a = {1.0};
  const std::vector<double> b = {2.0};
  const nlohmann::json j = nlohmann::json::parse(nlohmann::json(describe_pairs(a, b)).dump());
  EXPECT_TRUE(j.at("rmse").is_null());
  EXPECT_TRUE(j.at("mean_difference").is_null());
  EXPECT_EQ(j.at("n_used"), 1);
  EXPECT_FALSE(j.at("reason").get<std::string>().empty());
}

}  // namespace lmc::descriptives_test
