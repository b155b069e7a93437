#pragma once
// The complete pairs of two equally long series. A pair with NaN (or ±inf) on either side is
// dropped and counted, never replaced: a frame the LMC did not see must not count as 0 mm.
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace lmc {

// True for a value that can enter a statistic (finite); NaN marks missing data throughout core/.
inline bool is_usable(double v) {
  return std::isfinite(v);
}

struct PairedValues {
  std::vector<double> a;  // the complete pairs, in input order
  std::vector<double> b;
  std::size_t n_skipped = 0;  // pairs with a missing value on either side
};

// Throws lmc::Error when the two series differ in length (a programming error upstream, not data).
PairedValues complete_pairs(std::span<const double> a, std::span<const double> b);

}  // namespace lmc
