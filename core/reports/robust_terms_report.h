#pragma once
// The robust metric's terms as text and JSON (what `lmc optimize` and `lmc evaluate` print).
// JSON keys: "M", "redundancy", "participation", "axis_cut", "centring", "footprint", "inside_cut",
// "R", and "weights" {the same names but M} (robust_term_infos()).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/metric/robust_metric.h"

namespace lmc {

std::string format_robust_terms(const RobustTerms& terms, const RobustWeights& weights);
// One row per term, one column per split (e.g. all / horizontal / vertical poses).
std::string format_robust_terms_split(const std::vector<std::string>& split_names,
                                      const std::vector<RobustTerms>& splits, const RobustWeights& weights);
nlohmann::json robust_terms_to_json(const RobustTerms& terms, const RobustWeights& weights);

}  // namespace lmc
