// bland_altman_repeated() against a published worked example with unequal repeats per subject.
//
// Source: Bland JM, Altman DG (2007). Agreement between methods of measurement with multiple
// observations per individual. J Biopharm Stat 17:571–582, doi:10.1080/10543400701329422 — the
// worked example for the case where the true value varies (data: their Table 1, results from p. 575
// on). Cardiac output (l/min) of 12 subjects measured 3 to 6 times in pairs by radionuclide
// ventriculography (RV) and impedance cardiography (IC), 60 pairs in all (data of Bowling et al.
// 1993, Crit Care Med 21:1523–1527; the same pairs are Table 4 of Bland & Altman 1999, Stat Methods
// Med Res 8:135–160). Differences are RV − IC.
//
// Published results (printed to the digits below): one-way ANOVA of the differences by subject,
// subject MS 4.2090856 (11 df), residual MS 0.170714026 (48 df); divisor
// (60² − Σm_i²)/((12 − 1)·60) = 4.9818182 with Σm_i² = 312; variance of a difference
// 0.98133606, SD 0.99062408; mean difference 0.6021667; 95 % limits of agreement
// 0.6021667 ± 1.96 × 0.99062408 = −1.3394565 to 2.5437899.
//
// Two differences from the paper's arithmetic, both checked below:
//  * The paper multiplies by 1.96; bland_altman_repeated() uses z_{0.975} = 1.959964, which moves
//    each limit inward by (1.96 − z)·SD = 3.6e-5.
//  * The paper's software held the data in single precision: computed in double precision the
//    residual MS is 0.170713993 (not …026), the subject MS 4.2090861 (not …856), the variance
//    0.98133612 and the lower limit −1.3394566: the subject MS is 4.6e-7 off, every other figure
//    less than 1e-7. With the 60 pairs rounded to float first, every printed digit is reproduced.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/stats/bland_altman_repeated.h"

namespace lmc::bland_altman_published_test {

struct CardiacOutputPair {
  int subject;
  double rv;  // radionuclide ventriculography
  double ic;  // impedance cardiography
};

// Bland & Altman 2007, Table 1 (= Bland & Altman 1999, Table 4); m_i = 5, 4, 6, 5, 6, 4, 4, 6, 3,
// 5, 6, 6.
constexpr std::array<CardiacOutputPair, 60> kCardiacOutput = {{
    {1, 7.83, 6.57},  {1, 7.42, 5.62},  {1, 7.89, 6.90},  {1, 7.12, 6.57},  {1, 7.88, 6.35},  {2, 6.16, 4.06},
    {2, 7.26, 4.29},  {2, 6.71, 4.26},  {2, 6.54, 4.09},  {3, 4.75, 4.71},  {3, 5.24, 5.50},  {3, 4.86, 5.08},
    {3, 4.78, 5.02},  {3, 6.05, 6.01},  {3, 5.42, 5.67},  {4, 4.21, 4.14},  {4, 3.61, 4.20},  {4, 3.72, 4.61},
    {4, 3.87, 4.68},  {4, 3.92, 5.04},  {5, 3.13, 3.03},  {5, 2.98, 2.86},  {5, 2.85, 2.77},  {5, 3.17, 2.46},
    {5, 3.09, 2.32},  {5, 3.12, 2.43},  {6, 5.92, 5.90},  {6, 6.42, 5.81},  {6, 5.92, 5.70},  {6, 6.27, 5.76},
    {7, 7.13, 5.09},  {7, 6.62, 4.63},  {7, 6.58, 4.61},  {7, 6.93, 5.09},  {8, 4.54, 4.72},  {8, 4.81, 4.61},
    {8, 5.11, 4.36},  {8, 5.29, 4.20},  {8, 5.39, 4.36},  {8, 5.57, 4.20},  {9, 4.48, 3.17},  {9, 4.92, 3.12},
    {9, 3.97, 2.96},  {10, 4.22, 4.35}, {10, 4.65, 4.62}, {10, 4.74, 3.16}, {10, 4.44, 3.53}, {10, 4.50, 3.53},
    {11, 6.78, 7.20}, {11, 6.07, 6.09}, {11, 6.52, 7.00}, {11, 6.42, 7.10}, {11, 6.41, 7.40}, {11, 5.76, 6.80},
    {12, 5.06, 4.50}, {12, 4.72, 4.20}, {12, 4.90, 3.80}, {12, 4.80, 3.80}, {12, 4.90, 4.20}, {12, 5.10, 4.50},
}};

// The published numbers.
constexpr double kSubjectMs = 4.2090856;
constexpr double kResidualMs = 0.170714026;
constexpr double kDivisor = 4.9818182;
constexpr double kVariance = 0.98133606;
constexpr double kSd = 0.99062408;
constexpr double kBias = 0.6021667;
constexpr double kLowerLimit = -1.3394565;
constexpr double kUpperLimit = 2.5437899;
constexpr double kPaperMultiplier = 1.96;

// A = RV (first), B = IC, so A − B is the paper's RV − IC; single_precision rounds each value to
// float first, as the paper's software stored them.
std::vector<PairedObservation> cardiac_output(bool single_precision) {
  std::vector<PairedObservation> obs;
  obs.reserve(kCardiacOutput.size());
  for (const CardiacOutputPair& p : kCardiacOutput) {
    const double rv = single_precision ? static_cast<double>(static_cast<float>(p.rv)) : p.rv;
    const double ic = single_precision ? static_cast<double>(static_cast<float>(p.ic)) : p.ic;
    obs.push_back({"subject " + std::to_string(p.subject), rv, ic});
  }
  return obs;
}

// The ANOVA divisor from the group sizes, counted from the data.
double divisor_from_data() {
  std::array<double, 13> m{};
  for (const CardiacOutputPair& p : kCardiacOutput) m[static_cast<std::size_t>(p.subject)] += 1.0;
  double sum_m2 = 0.0;
  for (const double mi : m) sum_m2 += mi * mi;
  const double N = static_cast<double>(kCardiacOutput.size());
  return (N * N - sum_m2) / (11.0 * N);
}

TEST(StatsBlandAltmanPublished, CardiacOutputTrueValueVariesMatchesBlandAltman2007) {
  const BlandAltmanResult r = bland_altman_repeated(cardiac_output(false));
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_EQ(r.n_used, 60u);
  EXPECT_EQ(r.n_skipped, 0u);
  EXPECT_EQ(r.n_subjects, 12u);
  EXPECT_NEAR(divisor_from_data(), kDivisor, 5e-8);

  // Double precision: within 1e-7 of the published figures except the subject MS (4.6e-7 off) and
  // the between-subject variance derived from it (1.0e-7 off), see above.
  EXPECT_NEAR(r.bias, kBias, 5e-8);
  const double var_within = r.within_subject_sd * r.within_subject_sd;
  const double var_between = r.between_subject_sd * r.between_subject_sd;
  EXPECT_NEAR(var_within, kResidualMs, 1e-7);
  EXPECT_NEAR(divisor_from_data() * var_between + var_within, kSubjectMs, 5e-7);  // subject MS
  EXPECT_NEAR(var_between, (kSubjectMs - kResidualMs) / kDivisor, 2e-7);
  EXPECT_NEAR(r.sd_difference * r.sd_difference, kVariance, 1e-7);
  EXPECT_NEAR(r.sd_difference, kSd, 5e-8);

  // The limits with the paper's multiplier 1.96 ...
  EXPECT_NEAR(r.bias - kPaperMultiplier * r.sd_difference, kLowerLimit, 1e-7);
  EXPECT_NEAR(r.bias + kPaperMultiplier * r.sd_difference, kUpperLimit, 5e-8);
  // ... and as reported, with z_{0.975}: each limit 3.6e-5 inside the published one.
  EXPECT_NEAR(r.loa_multiplier, 1.959964, 5e-7);
  const double shift = (kPaperMultiplier - r.loa_multiplier) * kSd;
  EXPECT_NEAR(shift, 3.57e-5, 5e-8);
  EXPECT_NEAR(r.loa_low, kLowerLimit + shift, 1e-7);
  EXPECT_NEAR(r.loa_high, kUpperLimit - shift, 5e-8);
  EXPECT_NEAR(r.loa_low, kLowerLimit, 4e-5);
  EXPECT_NEAR(r.loa_high, kUpperLimit, 4e-5);
}

TEST(StatsBlandAltmanPublished, CardiacOutputInSinglePrecisionGivesEveryPrintedDigit) {
  // The same pairs rounded to float: each published figure to half a unit of its last printed
  // digit (the SD to one unit: 0.9906240748 against the printed 0.99062408).
  const BlandAltmanResult r = bland_altman_repeated(cardiac_output(true));
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_NEAR(r.bias, kBias, 5e-8);
  const double var_within = r.within_subject_sd * r.within_subject_sd;
  const double var_between = r.between_subject_sd * r.between_subject_sd;
  EXPECT_NEAR(var_within, kResidualMs, 5e-10);
  EXPECT_NEAR(divisor_from_data() * var_between + var_within, kSubjectMs, 5e-8);
  EXPECT_NEAR(r.sd_difference * r.sd_difference, kVariance, 5e-9);
  EXPECT_NEAR(r.sd_difference, kSd, 1e-8);
  EXPECT_NEAR(r.bias - kPaperMultiplier * r.sd_difference, kLowerLimit, 5e-8);
  EXPECT_NEAR(r.bias + kPaperMultiplier * r.sd_difference, kUpperLimit, 5e-8);
}

}  // namespace lmc::bland_altman_published_test
