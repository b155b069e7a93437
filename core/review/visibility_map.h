#pragma once
// The study's visibility-rate map: how often each controller saw each finger, per motion and
// layout — the figure that shows which controller an optimised layout relieves. The rate values
// and their mean follow `lmc report` exactly (summary_visibility() and mean_sd(): −1 "never saw
// the hand" is averaged in as the paper does, null is skipped), so the map and the report's table
// can never disagree.
#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/common/nan.h"
#include "core/review/agreement_input.h"

namespace lmc {

struct VisibilityCell {
  std::string device;  // "LMC1" … "LMC4"
  std::string motion;
  std::string layout;
  std::size_t trials = 0;     // trials that listed this device
  int values = 0;             // rates averaged (fingers × trials, nulls left out)
  std::size_t never_saw = 0;  // of those, rates of −1 (the device never saw the hand)
  double rate_mean = kNaN;    // NaN when no value
  double rate_sd = kNaN;      // NaN with fewer than 2 values
};

struct VisibilityMap {
  std::vector<VisibilityCell> cells;  // ordered by device, then motion, then layout
};

// Every trial counts (Vicon is not needed to see the hand).
VisibilityMap visibility_map(const std::vector<AgreementTrial>& trials);

// Header row, then one row per cell; NaN is an empty cell.
std::string visibility_map_csv(const VisibilityMap& map);

void to_json(nlohmann::json& j, const VisibilityCell& c);
void to_json(nlohmann::json& j, const VisibilityMap& m);

}  // namespace lmc
