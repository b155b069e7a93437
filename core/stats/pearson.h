#pragma once
// Pearson's product-moment correlation of paired series with a confidence interval from Fisher's
// z transform: z = atanh(r), SE = 1/sqrt(n − 3), CI = tanh(z ± z_{1−α/2}·SE) (Fisher 1921). The
// interval needs n ≥ 4 pairs; r itself needs n ≥ 3 (two points always give r = ±1) and non-zero
// spread on both sides. Pairs with a missing value on either side are skipped and counted.
#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>

#include "core/stats/interval.h"

namespace lmc {

struct PearsonResult {
  std::size_t n_used = 0;
  std::size_t n_skipped = 0;
  double r = kNaN;
  Interval ci;  // 95 % unless another level was asked for
  double level = 0.95;
  std::string reason;  // why r or its interval is NaN; empty when both are valid
  bool ok() const { return reason.empty(); }
};

// Throws lmc::Error when a and b differ in length or level is not in (0, 1).
PearsonResult pearson(std::span<const double> a, std::span<const double> b, double level = 0.95);

void to_json(nlohmann::json& j, const PearsonResult& r);

}  // namespace lmc
