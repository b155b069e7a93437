#include "core/stats/bland_altman_repeated.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "core/stats/paired_values.h"
#include "core/stats/quantiles.h"

namespace lmc {
namespace {

// A scaled mean square coef·MS with df degrees of freedom and its exact 95 % χ² interval.
struct VarianceTerm {
  double value = 0.0;
  double low = 0.0;
  double high = 0.0;
};

VarianceTerm chi_squared_term(double coef, double ms, double df) {
  VarianceTerm t;
  t.value = coef * ms;
  if (df <= 0.0 || t.value == 0.0) {
    t.low = t.high = t.value;
    return t;
  }
  t.low = t.value * df / chi_squared_quantile(0.975, df);
  t.high = t.value * df / chi_squared_quantile(0.025, df);
  return t;
}

// Differences per subject; groups are in order of first appearance, the map only finds them.
// Counts the used and skipped pairs into `r`.
std::vector<std::vector<double>> differences_by_subject(std::span<const PairedObservation> observations,
                                                        BlandAltmanResult& r) {
  std::map<std::string, std::size_t> index;
  std::vector<std::vector<double>> groups;
  for (const PairedObservation& o : observations) {
    if (!is_usable(o.a) || !is_usable(o.b)) {
      ++r.n_skipped;
      continue;
    }
    const auto [it, inserted] = index.emplace(o.subject, groups.size());
    if (inserted) groups.emplace_back();
    groups[it->second].push_back(o.a - o.b);
    ++r.n_used;
  }
  return groups;
}

// One subject: the bias (the mean difference over its trials) and the spread between its
// trials need no second subject; the limits and every CI do, since subjects are the unit of
// replication and one subject says nothing about how the bias varies between subjects.
void describe_one_subject(const std::vector<double>& differences, BlandAltmanResult& r) {
  double sum = 0.0;
  for (const double d : differences) sum += d;
  r.bias = sum / static_cast<double>(r.n_used);
  if (r.n_used >= 2) {
    double ss = 0.0;
    for (const double d : differences) ss += (d - r.bias) * (d - r.bias);
    r.within_subject_sd = std::sqrt(ss / static_cast<double>(r.n_used - 1));
  }
  r.reason = "the limits of agreement and the CIs need at least 2 subjects with complete pairs (1 subject, " +
             std::to_string(r.n_used) + " pairs usable); the bias is the mean difference over its trials";
}

// The one-way analysis of variance of the differences by subject (unequal group sizes).
struct RepeatedAnova {
  double n = 0, N = 0;  // subjects, observations
  double sum_m2 = 0;    // Σ m_i², m_i the observations of subject i
  double bias = 0;      // the mean of every difference
  double df_between = 0, df_within = 0, ms_between = 0, ms_within = 0;
  double c = 0;  // the divisor of the between-subject variance component
};

RepeatedAnova repeated_anova(const std::vector<std::vector<double>>& groups, std::size_t n_used) {
  RepeatedAnova a;
  a.n = static_cast<double>(groups.size());
  a.N = static_cast<double>(n_used);
  double sum = 0.0;
  for (const auto& g : groups) {
    for (const double d : g) sum += d;
    a.sum_m2 += static_cast<double>(g.size()) * static_cast<double>(g.size());
  }
  a.bias = sum / a.N;
  double ss_between = 0.0, ss_within = 0.0;
  for (const auto& g : groups) {
    double gsum = 0.0;
    for (const double d : g) gsum += d;
    const double gmean = gsum / static_cast<double>(g.size());
    ss_between += static_cast<double>(g.size()) * (gmean - a.bias) * (gmean - a.bias);
    for (const double d : g) ss_within += (d - gmean) * (d - gmean);
  }
  a.df_between = a.n - 1.0;
  a.df_within = a.N - a.n;  // 0 when every subject has one observation
  a.ms_between = ss_between / a.df_between;
  a.ms_within = a.df_within > 0.0 ? ss_within / a.df_within : 0.0;
  a.c = (a.N * a.N - a.sum_m2) / (a.df_between * a.N);
  return a;
}

// The limits' CIs by MOVER for SD² = MS_between/c + (1 − 1/c)·MS_within (the untruncated
// estimate), combined with the bias CI already in `r`.
void mover_limit_cis(const RepeatedAnova& a, double var_total, BlandAltmanResult& r) {
  const double c = a.c;
  const VarianceTerm tb = chi_squared_term(1.0 / c, a.ms_between, a.df_between);
  const VarianceTerm tw = chi_squared_term(1.0 - 1.0 / c, a.ms_within, a.df_within);
  const double var_sum = tb.value + tw.value;
  double var_low = var_sum - std::hypot(tb.value - tb.low, tw.value - tw.low);
  double var_high = var_sum + std::hypot(tb.high - tb.value, tw.high - tw.value);
  var_low = std::max(0.0, std::min(var_low, var_total));
  var_high = std::max(var_high, var_total);

  const double z = r.loa_multiplier;
  const double zs = z * r.sd_difference;
  const double zs_low = z * std::sqrt(var_low);
  const double zs_high = z * std::sqrt(var_high);
  const double bias_down = r.bias - r.bias_ci.low;
  const double bias_up = r.bias_ci.high - r.bias;
  // Upper limit = bias + zσ: both parts move it the same way.
  r.loa_high_ci = {r.loa_high - std::hypot(bias_down, zs - zs_low), r.loa_high + std::hypot(bias_up, zs_high - zs)};
  // Lower limit = bias − zσ: a larger σ moves it down.
  r.loa_low_ci = {r.loa_low - std::hypot(bias_down, zs_high - zs), r.loa_low + std::hypot(bias_up, zs - zs_low)};
}

}  // namespace

BlandAltmanResult bland_altman_repeated(std::span<const PairedObservation> observations) {
  BlandAltmanResult r;
  r.method =
      "Bland & Altman 2007 repeated measures (true value varies); bias CI t(n-1) on variance "
      "components; "
      "limit CIs by MOVER (Zou 2013)";
  r.loa_multiplier = normal_quantile(0.975);

  const std::vector<std::vector<double>> groups = differences_by_subject(observations, r);
  r.n_subjects = groups.size();
  if (groups.size() == 1) {
    describe_one_subject(groups[0], r);
    return r;
  }
  if (r.n_used < 2 || groups.size() < 2) {
    r.reason = "needs at least 2 subjects with complete pairs (" + std::to_string(groups.size()) + " subjects, " +
               std::to_string(r.n_used) + " pairs usable)";
    return r;
  }

  const RepeatedAnova a = repeated_anova(groups, r.n_used);
  r.bias = a.bias;
  const double var_within = a.ms_within;
  const double var_between = std::max(0.0, (a.ms_between - a.ms_within) / a.c);
  const double var_total = var_between + var_within;
  r.within_subject_sd = std::sqrt(var_within);
  r.between_subject_sd = std::sqrt(var_between);
  r.sd_difference = std::sqrt(var_total);
  r.loa_low = r.bias - r.loa_multiplier * r.sd_difference;
  r.loa_high = r.bias + r.loa_multiplier * r.sd_difference;

  const double t = t_quantile(0.975, a.df_between);
  const double se_bias = std::sqrt(var_between * a.sum_m2 / (a.N * a.N) + var_within / a.N);
  r.bias_ci = {r.bias - t * se_bias, r.bias + t * se_bias};
  mover_limit_cis(a, var_total, r);
  return r;
}

}  // namespace lmc
