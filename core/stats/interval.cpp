#include "core/stats/interval.h"

#include <nlohmann/json.hpp>

namespace lmc {

void to_json(nlohmann::json& j, const Interval& ci) {
  j = nlohmann::json{{"low", ci.low}, {"high", ci.high}};
}

}  // namespace lmc
