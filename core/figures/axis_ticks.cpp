#include "core/figures/axis_ticks.h"

#include "core/figures/locale_free_number.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lmc {

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> out;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || target < 1) return out;
  const double raw = (hi - lo) / target;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  // The round step whose count of ticks inside [lo, hi] comes closest to `target`; a step that
  // leaves fewer than two ticks (no scale to read) only when every step does.
  double step = power, best = std::numeric_limits<double>::infinity();
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    const double s = m * power;
    const double count = std::floor(hi / s + 1e-9) - std::ceil(lo / s - 1e-9) + 1;
    const double miss = std::abs(count - target) + (count < 2 ? 1e6 : 0.0);
    if (miss < best) {
      best = miss;
      step = s;
    }
  }
  const double first = std::ceil(lo / step) * step;
  for (double v = first; v <= hi + step * 1e-9; v += step) out.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
  return out;
}

std::pair<double, double> fit_y_range(std::span<const std::span<const double>> xs,
                                      std::span<const std::span<const double>> ys, double x_lo, double x_hi,
                                      double margin) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (size_t s = 0; s < xs.size() && s < ys.size(); ++s) {
    const auto& x = xs[s];
    const auto& y = ys[s];
    const size_t begin = static_cast<size_t>(std::lower_bound(x.begin(), x.end(), x_lo) - x.begin());
    const size_t end = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), x_hi) - x.begin());
    for (size_t i = begin; i < end && i < y.size(); ++i) {
      if (!std::isfinite(y[i])) continue;
      lo = std::min(lo, y[i]);
      hi = std::max(hi, y[i]);
    }
  }
  if (!(hi >= lo)) return {0.0, 1.0};
  if (hi == lo) return {lo - 1.0, hi + 1.0};
  const double pad = (hi - lo) * margin;
  return {lo - pad, hi + pad};
}

std::string tick_label(double value, const std::vector<double>& ticks) {
  const double step = ticks.size() >= 2 ? ticks[1] - ticks[0] : 1.0;
  int decimals = 0;
  if (step > 0 && step < 1) decimals = std::min(12, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  return fixed_c(value, decimals);
}

std::string value_label(double value, double lo, double hi) {
  const double span = hi - lo;
  int decimals = 2;
  if (std::isfinite(span) && span > 0) {
    decimals = std::clamp(static_cast<int>(std::ceil(2.0 - std::log10(span) - 1e-9)), 0, 12);
  }
  return fixed_c(value, decimals);
}

}  // namespace lmc
