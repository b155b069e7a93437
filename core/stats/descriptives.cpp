#include "core/stats/descriptives.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/stats/paired_values.h"

namespace lmc {
namespace {

std::string too_few(std::size_t n, const char* what) {
  return "fewer than 2 " + std::string(what) + " (" + std::to_string(n) + " usable)";
}

}  // namespace

double mean_of(std::span<const double> values) {
  if (values.empty()) return kNaN;
  double sum = 0.0;
  for (const double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

// Two passes (mean first, then squared deviations): the one-pass sum-of-squares formula loses
// digits when values are large compared with their spread (e.g. lengths in mm around 80 ± 0.1).
double sample_sd_of(std::span<const double> values) {
  if (values.size() < 2) return kNaN;
  const double m = mean_of(values);
  double ss = 0.0;
  for (const double v : values) ss += (v - m) * (v - m);
  return std::sqrt(ss / static_cast<double>(values.size() - 1));
}

Descriptives describe(std::span<const double> values) {
  std::vector<double> used;
  used.reserve(values.size());
  for (const double v : values)
    if (is_usable(v)) used.push_back(v);
  Descriptives d;
  d.n_used = used.size();
  d.n_skipped = values.size() - used.size();
  if (used.size() < 2) {
    d.reason = too_few(used.size(), "values");
    return d;
  }
  d.mean = mean_of(used);
  d.sd = sample_sd_of(used);
  return d;
}

PairedDescriptives describe_pairs(std::span<const double> a, std::span<const double> b) {
  const PairedValues p = complete_pairs(a, b);
  PairedDescriptives d;
  d.n_used = p.a.size();
  d.n_skipped = p.n_skipped;
  if (p.a.size() < 2) {
    d.reason = too_few(p.a.size(), "complete pairs");
    return d;
  }
  std::vector<double> diff(p.a.size());
  double sum_abs = 0.0, sum_sq = 0.0;
  for (std::size_t i = 0; i < diff.size(); ++i) {
    diff[i] = p.a[i] - p.b[i];
    sum_abs += std::abs(diff[i]);
    sum_sq += diff[i] * diff[i];
  }
  const auto n = static_cast<double>(diff.size());
  d.mean_a = mean_of(p.a);
  d.sd_a = sample_sd_of(p.a);
  d.mean_b = mean_of(p.b);
  d.sd_b = sample_sd_of(p.b);
  d.mean_difference = mean_of(diff);
  d.sd_difference = sample_sd_of(diff);
  d.mean_abs_difference = sum_abs / n;
  d.rmse = std::sqrt(sum_sq / n);
  return d;
}

void to_json(nlohmann::json& j, const Descriptives& d) {
  j = nlohmann::json{
      {"n_used", d.n_used}, {"n_skipped", d.n_skipped}, {"mean", d.mean}, {"sd", d.sd}, {"reason", d.reason}};
}

void to_json(nlohmann::json& j, const PairedDescriptives& d) {
  j = nlohmann::json{{"n_used", d.n_used},
                     {"n_skipped", d.n_skipped},
                     {"mean_a", d.mean_a},
                     {"sd_a", d.sd_a},
                     {"mean_b", d.mean_b},
                     {"sd_b", d.sd_b},
                     {"mean_difference", d.mean_difference},
                     {"sd_difference", d.sd_difference},
                     {"mean_abs_difference", d.mean_abs_difference},
                     {"rmse", d.rmse},
                     {"reason", d.reason}};
}

}  // namespace lmc
