#include "core/stats/bland_altman_repeated.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/stats/quantiles.h"

namespace lmc::bland_altman_repeated_test {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

double z975() {
  return lmc::normal_quantile(0.975);
}
double t975(double df) {
  return lmc::t_quantile(0.975, df);
}
double chi2(double p, double df) {
  return lmc::chi_squared_quantile(p, df);
}

// Subject i has `repeats` identical trials with difference A − B = diffs[i] (B = 50).
std::vector<PairedObservation> identical_repeats(const std::vector<double>& diffs, int repeats) {
  std::vector<PairedObservation> obs;
  for (std::size_t i = 0; i < diffs.size(); ++i)
    for (int r = 0; r < repeats; ++r) obs.push_back({"S" + std::to_string(i), 50.0 + diffs[i], 50.0});
  return obs;
}

TEST(StatsBlandAltmanRepeated, IdenticalRepeatsReduceToTheSimpleFormOnSubjectMeans) {
  // 4 subjects × 3 identical trials, differences 1, 3, 5, 7: within-subject variance 0, c = 3,
  // s²_db = MS_between/3 = the variance of the subject differences, 20/3 — as bland_altman() on
  // the four subject differences (bland_altman_test.cpp), except the limit CIs (MOVER).
  std::vector<PairedObservation> obs = identical_repeats({1, 3, 5, 7}, 3);
  obs.push_back({"S1", kMissing, 50.0});  // skipped and counted
  const BlandAltmanResult r = bland_altman_repeated(obs);
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_EQ(r.n_used, 12u);
  EXPECT_EQ(r.n_skipped, 1u);
  EXPECT_EQ(r.n_subjects, 4u);
  const double s = std::sqrt(20.0 / 3.0);
  EXPECT_NEAR(r.bias, 4.0, 1e-12);
  EXPECT_NEAR(r.within_subject_sd, 0.0, 1e-12);
  EXPECT_NEAR(r.between_subject_sd, s, 1e-12);
  EXPECT_NEAR(r.sd_difference, s, 1e-12);
  EXPECT_NEAR(r.loa_low, 4.0 - z975() * s, 1e-9);
  EXPECT_NEAR(r.loa_high, 4.0 + z975() * s, 1e-9);
  const double h = t975(3.0) * s / 2.0;  // the simple form's bias half-width, t(n − 1) with n subjects
  EXPECT_NEAR(r.bias_ci.low, 4.0 - h, 1e-9);
  EXPECT_NEAR(r.bias_ci.high, 4.0 + h, 1e-9);
  // MOVER with only the between-subject term: s² has the exact χ²(3) interval.
  const double zs = z975() * s;
  const double zs_low = z975() * std::sqrt(s * s * 3.0 / chi2(0.975, 3.0));
  const double zs_high = z975() * std::sqrt(s * s * 3.0 / chi2(0.025, 3.0));
  EXPECT_NEAR(r.loa_high_ci.low, r.loa_high - std::hypot(h, zs - zs_low), 1e-9);
  EXPECT_NEAR(r.loa_high_ci.high, r.loa_high + std::hypot(h, zs_high - zs), 1e-9);
  EXPECT_NEAR(r.loa_low_ci.low, r.loa_low - std::hypot(h, zs_high - zs), 1e-9);
  EXPECT_NEAR(r.loa_low_ci.high, r.loa_low + std::hypot(h, zs - zs_low), 1e-9);
}

TEST(StatsBlandAltmanRepeated, OneTrialPerSubjectMatchesTheSimpleForm) {
  const std::vector<double> a = {11, 13, 15, 17, 12};
  const std::vector<double> b = {10, 10, 10, 10, 9};
  std::vector<PairedObservation> obs;
  for (std::size_t i = 0; i < a.size(); ++i) obs.push_back({"S" + std::to_string(i), a[i], b[i]});
  const BlandAltmanResult rep = bland_altman_repeated(obs);
  const BlandAltmanResult simple = bland_altman(a, b);
  ASSERT_TRUE(rep.ok()) << rep.reason;
  EXPECT_NEAR(rep.bias, simple.bias, 1e-12);
  EXPECT_NEAR(rep.sd_difference, simple.sd_difference, 1e-12);
  EXPECT_NEAR(rep.loa_low, simple.loa_low, 1e-12);
  EXPECT_NEAR(rep.loa_high, simple.loa_high, 1e-12);
  EXPECT_NEAR(rep.bias_ci.low, simple.bias_ci.low, 1e-9);
  EXPECT_NEAR(rep.bias_ci.high, simple.bias_ci.high, 1e-9);
}

TEST(StatsBlandAltmanRepeated, UnequalTrialsFollowTheAnovaFormByHand) {
  // A: 1, 3 (m = 2); B: 4 (m = 1); C: 6, 8, 10 (m = 3). N = 6, n = 3, bias = 32/6.
  // SS_between = 2(2 − 16/3)² + (4 − 16/3)² + 3(8 − 16/3)² = 408/9 → MS_between = 68/3;
  // SS_within = 2 + 0 + 8 = 10 → MS_within = 10/3; c = (36 − 14)/(2·6) = 11/6;
  // s²_db = (68/3 − 10/3)/(11/6) = 116/11; s²_d = 116/11 + 10/3 = 458/33.
  const std::vector<PairedObservation> obs = {{"A", 1, 0}, {"B", 4, 0},  {"C", 6, 0},       {"A", 3, 0},
                                              {"C", 8, 0}, {"C", 10, 0}, {"B", kMissing, 0}};
  const BlandAltmanResult r = bland_altman_repeated(obs);
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_EQ(r.n_used, 6u);
  EXPECT_EQ(r.n_skipped, 1u);
  EXPECT_EQ(r.n_subjects, 3u);
  EXPECT_NEAR(r.bias, 16.0 / 3.0, 1e-12);
  EXPECT_NEAR(r.within_subject_sd, std::sqrt(10.0 / 3.0), 1e-12);
  EXPECT_NEAR(r.between_subject_sd, std::sqrt(116.0 / 11.0), 1e-12);
  EXPECT_NEAR(r.sd_difference, std::sqrt(458.0 / 33.0), 1e-12);
  EXPECT_NEAR(r.loa_high, 16.0 / 3.0 + z975() * std::sqrt(458.0 / 33.0), 1e-9);
  const double se_bias = std::sqrt(116.0 / 11.0 * 14.0 / 36.0 + 10.0 / 3.0 / 6.0);
  EXPECT_NEAR(r.bias_ci.high - r.bias, t975(2.0) * se_bias, 1e-9);
  // The MOVER limits enclose their estimates, and the lower limit's interval mirrors the upper's.
  EXPECT_LT(r.loa_high_ci.low, r.loa_high);
  EXPECT_GT(r.loa_high_ci.high, r.loa_high);
  EXPECT_LT(r.loa_low_ci.low, r.loa_low);
  EXPECT_GT(r.loa_low_ci.high, r.loa_low);
  EXPECT_NEAR(r.loa_high_ci.high - r.loa_high, r.loa_low - r.loa_low_ci.low, 1e-9);
  // Pooling the six trials as if independent understates the spread between subjects.
  std::vector<double> a, b;
  for (const auto& o : obs) {
    a.push_back(o.a);
    b.push_back(o.b);
  }
  EXPECT_LT(bland_altman(a, b).sd_difference, r.sd_difference);
}

TEST(StatsBlandAltmanRepeated, OneSubjectGivesTheBiasButNoLimitsAndNoDataIsNaN) {
  const std::vector<PairedObservation> one = {{"A", 1, 0}, {"A", 2, 0}, {"A", 4, 0}, {"B", kMissing, 1}};
  const BlandAltmanResult r = bland_altman_repeated(one);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.n_subjects, 1u);
  EXPECT_EQ(r.n_skipped, 1u);
  // Differences 1, 2, 4: the bias is their mean, the within-subject SD their sample SD.
  EXPECT_NEAR(r.bias, 7.0 / 3.0, 1e-12);
  EXPECT_NEAR(r.within_subject_sd, std::sqrt(7.0 / 3.0), 1e-12);
  EXPECT_TRUE(std::isnan(r.sd_difference));
  EXPECT_TRUE(std::isnan(r.loa_low));
  EXPECT_TRUE(std::isnan(r.loa_high));
  EXPECT_TRUE(std::isnan(r.bias_ci.low));
  EXPECT_TRUE(std::isnan(r.loa_low_ci.low));
  EXPECT_NE(r.reason.find("need at least 2 subjects"), std::string::npos) << r.reason;
  const BlandAltmanResult none = bland_altman_repeated(std::vector<PairedObservation>{});
  EXPECT_FALSE(none.ok());
  EXPECT_TRUE(nlohmann::json::parse(nlohmann::json(none).dump()).at("sd_difference").is_null());
}

}  // namespace lmc::bland_altman_repeated_test
