#pragma once
// The one "missing value" constant: NaN marks a value that was not measured (no hand, a marker
// Vicon lost, a statistic that cannot be computed). It is never replaced by 0.
#include <limits>

namespace lmc {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace lmc
