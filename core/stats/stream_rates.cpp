#include "core/stats/stream_rates.h"

#include <utility>
#include <vector>

#include "core/stats/percentile.h"

namespace lmc {

StreamRates stream_rates(std::span<const std::int64_t> timestamps_us) {
  StreamRates r;
  std::vector<double> rates;
  rates.reserve(timestamps_us.size());
  for (size_t i = 1; i < timestamps_us.size(); ++i) {
    const std::int64_t dt = timestamps_us[i] - timestamps_us[i - 1];
    if (dt > 0) rates.push_back(1e6 / static_cast<double>(dt));
  }
  r.intervals = static_cast<int>(rates.size());
  if (rates.empty()) return r;
  r.median_hz = percentile(rates, 50);
  r.p5_hz = percentile(rates, 5);
  r.p95_hz = percentile(std::move(rates), 95);
  return r;
}

}  // namespace lmc
