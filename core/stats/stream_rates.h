#pragma once
// A controller's frame rate from its timestamps: the rates 1 / Δt of consecutive frames, summarised
// by percentiles (percentile.h). One rule for the trial verdict and `lmc info`.
#include <cstdint>
#include <limits>
#include <span>

namespace lmc {

struct StreamRates {
  int intervals = 0;  // positive differences the rates come from
  double median_hz = std::numeric_limits<double>::quiet_NaN();
  double p5_hz = std::numeric_limits<double>::quiet_NaN();
  double p95_hz = std::numeric_limits<double>::quiet_NaN();
};

// `timestamps_us` in time order. A zero difference is a duplicate row, not an infinitely fast
// controller, and a negative one cannot happen in time order: both are left out. NaN rates when
// fewer than two distinct timestamps.
StreamRates stream_rates(std::span<const std::int64_t> timestamps_us);

}  // namespace lmc
