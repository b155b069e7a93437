#pragma once
// Linear-interpolation percentile (numpy's default) of unsorted values; NaN when empty. One rule
// for the trial verdict's rate percentiles and the live fusion's latency percentiles.
#include <vector>

namespace lmc {

// p in 0..100.
double percentile(std::vector<double> values, double p);

}  // namespace lmc
