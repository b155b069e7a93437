#include "core/stats/bland_altman.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/stats/descriptives.h"
#include "core/stats/paired_values.h"
#include "core/stats/quantiles.h"

namespace lmc {

BlandAltmanResult bland_altman(std::span<const double> a, std::span<const double> b) {
  const PairedValues p = complete_pairs(a, b);
  BlandAltmanResult r;
  r.method = "Bland & Altman 1986/1999, one pair per subject; limit CIs with SE = sqrt(3 s^2/n), t(n-1)";
  r.n_used = p.a.size();
  r.n_skipped = p.n_skipped;
  r.n_subjects = p.a.size();
  r.loa_multiplier = normal_quantile(0.975);
  if (p.a.size() < 2) {
    r.reason = "fewer than 2 complete pairs (" + std::to_string(p.a.size()) + " usable)";
    return r;
  }
  std::vector<double> d(p.a.size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = p.a[i] - p.b[i];
  const auto n = static_cast<double>(d.size());
  r.bias = mean_of(d);
  r.sd_difference = sample_sd_of(d);
  r.loa_low = r.bias - r.loa_multiplier * r.sd_difference;
  r.loa_high = r.bias + r.loa_multiplier * r.sd_difference;
  const double t = t_quantile(0.975, n - 1.0);
  const double se_bias = r.sd_difference / std::sqrt(n);
  const double se_limit = std::sqrt(3.0 * r.sd_difference * r.sd_difference / n);
  r.bias_ci = {r.bias - t * se_bias, r.bias + t * se_bias};
  r.loa_low_ci = {r.loa_low - t * se_limit, r.loa_low + t * se_limit};
  r.loa_high_ci = {r.loa_high - t * se_limit, r.loa_high + t * se_limit};
  return r;
}

std::vector<BlandAltmanPoint> bland_altman_points(std::span<const double> a, std::span<const double> b) {
  const PairedValues p = complete_pairs(a, b);
  std::vector<BlandAltmanPoint> points(p.a.size());
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = {(p.a[i] + p.b[i]) / 2.0, p.a[i] - p.b[i]};
  return points;
}

void to_json(nlohmann::json& j, const BlandAltmanResult& r) {
  j = nlohmann::json{{"method", r.method},
                     {"n_used", r.n_used},
                     {"n_skipped", r.n_skipped},
                     {"n_subjects", r.n_subjects},
                     {"bias", r.bias},
                     {"sd_difference", r.sd_difference},
                     {"loa_low", r.loa_low},
                     {"loa_high", r.loa_high},
                     {"bias_ci", r.bias_ci},
                     {"loa_low_ci", r.loa_low_ci},
                     {"loa_high_ci", r.loa_high_ci},
                     {"within_subject_sd", r.within_subject_sd},
                     {"between_subject_sd", r.between_subject_sd},
                     {"loa_multiplier", r.loa_multiplier},
                     {"level", 0.95},
                     {"difference", "A - B"},
                     {"reason", r.reason}};
}

}  // namespace lmc
