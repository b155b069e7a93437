#include "core/stats/pearson.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/stats/descriptives.h"
#include "core/stats/paired_values.h"
#include "core/stats/quantiles.h"

namespace lmc {

PearsonResult pearson(std::span<const double> a, std::span<const double> b, double level) {
  if (!(level > 0.0 && level < 1.0)) throw Error("confidence level must be in (0, 1), got " + std::to_string(level));
  const PairedValues p = complete_pairs(a, b);
  PearsonResult out;
  out.level = level;
  out.n_used = p.a.size();
  out.n_skipped = p.n_skipped;
  const std::size_t n = p.a.size();
  if (n < 3) {
    out.reason = "fewer than 3 complete pairs (" + std::to_string(n) + "): r is undefined or trivially ±1";
    return out;
  }
  const double ma = mean_of(p.a), mb = mean_of(p.b);
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sab += (p.a[i] - ma) * (p.b[i] - mb);
    saa += (p.a[i] - ma) * (p.a[i] - ma);
    sbb += (p.b[i] - mb) * (p.b[i] - mb);
  }
  if (saa == 0.0 || sbb == 0.0) {
    out.reason = "one series is constant: r is undefined";
    return out;
  }
  // Rounding can push |r| a hair past 1, which would make atanh NaN.
  out.r = std::clamp(sab / std::sqrt(saa * sbb), -1.0, 1.0);
  if (n < 4) {
    out.reason = "3 complete pairs: the Fisher-z interval needs at least 4";
    return out;
  }
  const double z = std::atanh(out.r);  // ±inf for r = ±1: the interval is then [r, r]
  const double half = normal_quantile(0.5 + level / 2.0) / std::sqrt(static_cast<double>(n) - 3.0);
  out.ci = {std::tanh(z - half), std::tanh(z + half)};
  return out;
}

void to_json(nlohmann::json& j, const PearsonResult& r) {
  j = nlohmann::json{{"n_used", r.n_used},
                     {"n_skipped", r.n_skipped},
                     {"r", r.r},
                     {"ci", r.ci},
                     {"level", r.level},
                     {"reason", r.reason},
                     {"method", "Pearson r; CI by Fisher z transform"}};
}

}  // namespace lmc
