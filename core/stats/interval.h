#pragma once
// A two-sided confidence interval. Both ends are NaN when it cannot be computed (too few values,
// zero variance where the method divides by it); the result that holds it says why in `reason`.
#include <limits>
#include <nlohmann/json_fwd.hpp>

#include "core/common/nan.h"

namespace lmc {

struct Interval {
  double low = kNaN;
  double high = kNaN;
};

// {"low": …, "high": …}; NaN is written as JSON null (nlohmann's rule), never as 0.
void to_json(nlohmann::json& j, const Interval& ci);

}  // namespace lmc
