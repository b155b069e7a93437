#include "core/stats/icc.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/stats/quantiles.h"

namespace lmc::icc_test {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

// Shrout & Fleiss (1979), Table 2: 6 targets rated by 4 judges.
Eigen::MatrixXd shrout_fleiss_table() {
  Eigen::MatrixXd x(6, 4);
  x << 9, 2, 5, 8,  //
      6, 1, 3, 2,   //
      8, 4, 6, 8,   //
      7, 1, 2, 6,   //
      10, 5, 6, 9,  //
      6, 2, 4, 7;
  return x;
}

double f975(double df1, double df2) {
  return lmc::f_quantile(0.975, df1, df2);
}

TEST(StatsIcc, ShroutFleissTable2ToThePublishedDecimals) {
  const IccResult r = icc(shrout_fleiss_table());
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_EQ(r.n_targets, 6u);
  EXPECT_EQ(r.k, 4u);
  // Their ANOVA mean squares (BMS, WMS, JMS, EMS) as printed.
  EXPECT_NEAR(r.bms, 11.24, 0.005);
  EXPECT_NEAR(r.wms, 6.26, 0.005);
  EXPECT_NEAR(r.jms, 32.49, 0.005);
  EXPECT_NEAR(r.ems, 1.02, 0.005);
  // Their published ICCs, to two decimals.
  EXPECT_NEAR(r.icc1_1.value, 0.17, 0.005);
  EXPECT_NEAR(r.icc2_1.value, 0.29, 0.005);
  EXPECT_NEAR(r.icc3_1.value, 0.71, 0.005);
  EXPECT_NEAR(r.icc1_k.value, 0.44, 0.005);
  EXPECT_NEAR(r.icc2_k.value, 0.62, 0.005);
  EXPECT_NEAR(r.icc3_k.value, 0.91, 0.005);
  EXPECT_EQ(r.icc2_1.description, "ICC(2,1): two-way random effects, absolute agreement, single measurement");
  EXPECT_EQ(r.icc3_k.form, "ICC(3,4)");
  EXPECT_EQ(r.icc3_k.description, "ICC(3,4): two-way mixed effects, consistency, average of 4 measurements");
  EXPECT_EQ(r.icc1_1.description, "ICC(1,1): one-way random effects, absolute agreement, single measurement");
}

TEST(StatsIcc, ExactFIntervalsAgainstBoostQuantiles) {
  const IccResult r = icc(shrout_fleiss_table());
  const double n = 6.0, k = 4.0;
  // ICC(1,·): F0 = BMS/WMS on (n − 1, n(k − 1)) df.
  const double f1 = r.bms / r.wms;
  const double fl1 = f1 / f975(n - 1, n * (k - 1)), fu1 = f1 * f975(n * (k - 1), n - 1);
  EXPECT_NEAR(r.icc1_1.ci.low, (fl1 - 1) / (fl1 + k - 1), 1e-9);
  EXPECT_NEAR(r.icc1_1.ci.high, (fu1 - 1) / (fu1 + k - 1), 1e-9);
  EXPECT_NEAR(r.icc1_k.ci.low, 1 - 1 / fl1, 1e-9);
  EXPECT_NEAR(r.icc1_k.ci.high, 1 - 1 / fu1, 1e-9);
  EXPECT_DOUBLE_EQ(r.icc1_1.f_df2, 18.0);
  // ICC(3,·): F0 = BMS/EMS on (n − 1, (n − 1)(k − 1)) df.
  const double f3 = r.bms / r.ems;
  const double fl3 = f3 / f975(n - 1, (n - 1) * (k - 1)), fu3 = f3 * f975((n - 1) * (k - 1), n - 1);
  EXPECT_NEAR(r.icc3_1.ci.low, (fl3 - 1) / (fl3 + k - 1), 1e-9);
  EXPECT_NEAR(r.icc3_1.ci.high, (fu3 - 1) / (fu3 + k - 1), 1e-9);
  EXPECT_NEAR(r.icc3_k.ci.low, 1 - 1 / fl3, 1e-9);
  EXPECT_NEAR(r.icc3_k.ci.high, 1 - 1 / fu3, 1e-9);
  EXPECT_NEAR(r.icc3_1.f_value, 11.03, 0.01);
  EXPECT_LT(r.icc3_1.p_value, 0.001);
}

TEST(StatsIcc, TwoWayRandomIntervalFollowsSatterthwaite) {
  const IccResult r = icc(shrout_fleiss_table());
  const double n = 6.0, k = 4.0, rho = r.icc2_1.value;
  // S&F's form of Satterthwaite's df (the library uses McGraw & Wong's equivalent form):
  // v = (n − 1)(k − 1)(kρ·Fj + b)² / ((n − 1)k²ρ²Fj² + b²), Fj = JMS/EMS, b = n(1 + (k − 1)ρ) − kρ.
  const double fj = r.jms / r.ems;
  const double b = n * (1 + (k - 1) * rho) - k * rho;
  const double v = (n - 1) * (k - 1) * std::pow(k * rho * fj + b, 2) / ((n - 1) * k * k * rho * rho * fj * fj + b * b);
  const double fs = f975(n - 1, v), fs2 = f975(v, n - 1);
  EXPECT_NEAR(r.icc2_1.ci.low, n * (r.bms - fs * r.ems) / (fs * (k * r.jms + (k * n - k - n) * r.ems) + n * r.bms),
              1e-9);
  EXPECT_NEAR(r.icc2_1.ci.high, n * (fs2 * r.bms - r.ems) / (k * r.jms + (k * n - k - n) * r.ems + n * fs2 * r.bms),
              1e-9);
  EXPECT_NEAR(r.icc2_k.ci.low, n * (r.bms - fs * r.ems) / (fs * (r.jms - r.ems) + n * r.bms), 1e-9);
  EXPECT_NEAR(r.icc2_k.ci.high, n * (fs2 * r.bms - r.ems) / ((r.jms - r.ems) + n * fs2 * r.bms), 1e-9);
  for (const IccEstimate* e : {&r.icc1_1, &r.icc2_1, &r.icc3_1, &r.icc1_k, &r.icc2_k, &r.icc3_k}) {
    EXPECT_LT(e->ci.low, e->value) << e->form;
    EXPECT_GT(e->ci.high, e->value) << e->form;
  }
}

TEST(StatsIcc, IntervalsMatchTheRPsychPackageOnTheSameTable) {
  // psych::ICC on Shrout & Fleiss's table prints these bounds (lower to 3 decimals, upper to 2):
  // an independent implementation of the same S&F / McGraw & Wong formulas.
  const IccResult r = icc(shrout_fleiss_table());
  EXPECT_NEAR(r.icc1_1.ci.low, -0.133, 5e-4);
  EXPECT_NEAR(r.icc1_1.ci.high, 0.72, 5e-3);
  EXPECT_NEAR(r.icc2_1.ci.low, 0.019, 5e-4);
  EXPECT_NEAR(r.icc2_1.ci.high, 0.76, 5e-3);
  EXPECT_NEAR(r.icc3_1.ci.low, 0.342, 5e-4);
  EXPECT_NEAR(r.icc3_1.ci.high, 0.95, 5e-3);
  EXPECT_NEAR(r.icc1_k.ci.low, -0.884, 5e-4);
  EXPECT_NEAR(r.icc1_k.ci.high, 0.91, 5e-3);
  EXPECT_NEAR(r.icc2_k.ci.low, 0.071, 5e-4);
  EXPECT_NEAR(r.icc2_k.ci.high, 0.93, 5e-3);
  EXPECT_NEAR(r.icc3_k.ci.low, 0.676, 5e-4);
  EXPECT_NEAR(r.icc3_k.ci.high, 0.99, 5e-3);
}

TEST(StatsIcc, HandComputedAgreementVersusConsistency) {
  // Rater 2 reads exactly 1 more than rater 1: perfect consistency, imperfect absolute agreement.
  // BMS = 8, JMS = 1.5, EMS = 0, WMS = 0.5 → ICC(3,1) = 1, ICC(2,1) = 8/9, ICC(1,1) = 7.5/8.5.
  Eigen::MatrixXd x(3, 2);
  x << 1, 2, 3, 4, 5, 6;
  const IccResult r = icc(x);
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_NEAR(r.bms, 8.0, 1e-12);
  EXPECT_NEAR(r.jms, 1.5, 1e-12);
  EXPECT_NEAR(r.ems, 0.0, 1e-12);
  EXPECT_NEAR(r.wms, 0.5, 1e-12);
  EXPECT_NEAR(r.icc3_1.value, 1.0, 1e-12);
  EXPECT_NEAR(r.icc2_1.value, 8.0 / 9.0, 1e-12);
  EXPECT_NEAR(r.icc1_1.value, 7.5 / 8.5, 1e-12);
  EXPECT_NEAR(r.icc2_k.value, 8.0 / 8.5, 1e-12);
  // EMS = 0: consistency is certain, its interval degenerates to [1, 1]; absolute agreement keeps a
  // finite interval (Satterthwaite's df falls back to JMS's k − 1 = 1).
  EXPECT_DOUBLE_EQ(r.icc3_1.ci.low, 1.0);
  EXPECT_DOUBLE_EQ(r.icc3_1.ci.high, 1.0);
  EXPECT_DOUBLE_EQ(r.icc3_k.ci.low, 1.0);
  const double fs = f975(2.0, 1.0);  // F*(n − 1, v = 1)
  EXPECT_NEAR(r.icc2_1.ci.low, 3.0 * 8.0 / (fs * 2.0 * 1.5 + 3.0 * 8.0), 1e-9);
  EXPECT_LT(r.icc2_1.ci.low, r.icc2_1.value);
  EXPECT_GT(r.icc2_1.ci.high, r.icc2_1.value);
}

TEST(StatsIcc, PerfectAgreementHasDegenerateIntervalsNotNaN) {
  Eigen::MatrixXd x(3, 2);
  x << 1, 1, 4, 4, 6, 6;
  const IccResult r = icc(x);
  ASSERT_TRUE(r.ok()) << r.reason;
  for (const IccEstimate* e : {&r.icc1_1, &r.icc2_1, &r.icc3_1, &r.icc1_k, &r.icc2_k, &r.icc3_k}) {
    EXPECT_DOUBLE_EQ(e->value, 1.0) << e->form;
    EXPECT_DOUBLE_EQ(e->ci.low, 1.0) << e->form;
    EXPECT_DOUBLE_EQ(e->ci.high, 1.0) << e->form;
  }
}

TEST(StatsIcc, RowsWithMissingValuesAreDroppedAndCounted) {
  Eigen::MatrixXd x(8, 4);
  x.topRows(6) = shrout_fleiss_table();
  x.row(6) << 1, kMissing, 3, 4;
  x.row(7) << kMissing, kMissing, kMissing, kMissing;
  const IccResult r = icc(x);
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_EQ(r.n_targets, 6u);
  EXPECT_EQ(r.n_dropped, 2u);
  const IccResult clean = icc(shrout_fleiss_table());
  EXPECT_DOUBLE_EQ(r.icc2_1.value, clean.icc2_1.value);
  EXPECT_DOUBLE_EQ(r.icc2_1.ci.low, clean.icc2_1.ci.low);
}

TEST(StatsIcc, TooFewRowsOrNoVariationIsNaNWithAReason) {
  Eigen::MatrixXd x(3, 2);
  x << 1, 2, kMissing, 3, 4, kMissing;
  const IccResult r = icc(x);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.n_targets, 1u);
  EXPECT_EQ(r.n_dropped, 2u);
  EXPECT_TRUE(std::isnan(r.icc2_1.value));
  EXPECT_TRUE(std::isnan(r.icc2_1.ci.low));
  EXPECT_EQ(r.icc2_1.form, "ICC(2,1)");  // still says what it would have been

  const IccResult flat = icc(Eigen::MatrixXd::Constant(4, 3, 2.0));
  EXPECT_FALSE(flat.ok());
  EXPECT_TRUE(std::isnan(flat.icc3_1.value));

  const IccResult one_column = icc(Eigen::MatrixXd::Ones(5, 1));
  EXPECT_FALSE(one_column.ok());
  const nlohmann::json j = nlohmann::json::parse(nlohmann::json(one_column).dump());
  EXPECT_TRUE(j.at("estimates").at(0).at("value").is_null());
  EXPECT_FALSE(j.at("reason").get<std::string>().empty());
}

TEST(StatsIcc, JsonNamesEveryForm) {
  const nlohmann::json j = icc(shrout_fleiss_table());
  ASSERT_EQ(j.at("estimates").size(), 6u);
  EXPECT_EQ(j.at("estimates").at(1).at("form"), "ICC(2,1)");
  EXPECT_NEAR(j.at("estimates").at(1).at("value").get<double>(), 0.29, 0.005);
  EXPECT_TRUE(j.at("estimates").at(1).at("ci").contains("low"));
}

}  // namespace lmc::icc_test
