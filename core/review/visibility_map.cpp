#include "core/review/visibility_map.h"

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>

#include "core/common/csv_cell.h"
#include "core/common/nan.h"
#include "core/common/number_format.h"
#include "core/reports/session_report.h"
#include "core/results/summary_reading.h"

namespace lmc {

namespace {

struct VisibilityRates {
  std::size_t trials = 0;
  std::vector<double> rates;
};

std::string visibility_number(double v) {
  return std::isfinite(v) ? format_fixed(v, 6) : std::string();
}

}  // namespace

VisibilityMap visibility_map(const std::vector<AgreementTrial>& trials) {
  std::map<std::tuple<std::string, std::string, std::string>, VisibilityRates> cells;
  for (const AgreementTrial& t : trials) {
    if (!t.summary.is_object()) continue;
    for (const DeviceVisibility& d : summary_visibility(t.summary)) {
      VisibilityRates& c = cells[{d.device, t.motion, t.layout}];
      ++c.trials;
      c.rates.insert(c.rates.end(), d.rates.begin(), d.rates.end());
    }
  }
  VisibilityMap map;
  for (const auto& [key, c] : cells) {
    const MeanSd m = mean_sd(c.rates);
    VisibilityCell cell{std::get<0>(key), std::get<1>(key), std::get<2>(key), c.trials, m.n, 0, m.mean, m.sd};
    for (double r : c.rates)
      if (r == -1.0) ++cell.never_saw;
    map.cells.push_back(std::move(cell));
  }
  return map;
}

std::string visibility_map_csv(const VisibilityMap& map) {
  std::ostringstream csv;
  csv << "device,motion,layout,trials,values,never_saw_hand,rate_mean,rate_sd\n";
  for (const VisibilityCell& c : map.cells)
    csv << csv_cell(c.device) << ',' << csv_cell(c.motion) << ',' << csv_cell(c.layout) << ',' << c.trials << ','
        << c.values << ',' << c.never_saw << ',' << visibility_number(c.rate_mean) << ','
        << visibility_number(c.rate_sd) << '\n';
  return csv.str();
}

void to_json(nlohmann::json& j, const VisibilityCell& c) {
  j = nlohmann::json{{"device", c.device},       {"motion", c.motion},  {"layout", c.layout},
                     {"trials", c.trials},       {"values", c.values},  {"never_saw_hand", c.never_saw},
                     {"rate_mean", c.rate_mean}, {"rate_sd", c.rate_sd}};
}

void to_json(nlohmann::json& j, const VisibilityMap& m) {
  j = nlohmann::json{{"cells", m.cells}};
}

}  // namespace lmc
