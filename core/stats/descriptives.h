#pragma once
// Descriptive statistics that skip missing values (NaN, ±inf) and say how many they used. With
// fewer than 2 usable values every number is NaN and `reason` says why: a missing statistic is
// never reported as 0.
#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>

#include "core/stats/interval.h"

namespace lmc {

struct Descriptives {
  std::size_t n_used = 0;     // finite values used
  std::size_t n_skipped = 0;  // NaN / ±inf values left out
  double mean = kNaN;
  double sd = kNaN;    // sample SD (divisor n − 1)
  std::string reason;  // empty when the numbers are valid
  bool ok() const { return reason.empty(); }
};

// Paired series: A is the method under test (e.g. fused LMC), B the reference (e.g. Vicon);
// differences are A − B. A pair with a missing value on either side is skipped as a whole.
struct PairedDescriptives {
  std::size_t n_used = 0;     // complete pairs used
  std::size_t n_skipped = 0;  // pairs with a missing value on either side
  double mean_a = kNaN, sd_a = kNaN;
  double mean_b = kNaN, sd_b = kNaN;
  double mean_difference = kNaN;      // mean of A − B (the bias)
  double sd_difference = kNaN;        // sample SD of A − B (n − 1)
  double mean_abs_difference = kNaN;  // mean |A − B|
  double rmse = kNaN;                 // sqrt(mean((A − B)²)): includes the bias, unlike sd_difference
  std::string reason;
  bool ok() const { return reason.empty(); }
};

Descriptives describe(std::span<const double> values);
// Throws lmc::Error when a and b differ in length.
PairedDescriptives describe_pairs(std::span<const double> a, std::span<const double> b);

void to_json(nlohmann::json& j, const Descriptives& d);
void to_json(nlohmann::json& j, const PairedDescriptives& d);

// Mean and sample SD of values that are all finite (callers filter first); NaN SD for n < 2.
double mean_of(std::span<const double> values);
double sample_sd_of(std::span<const double> values);

}  // namespace lmc
