#include "core/results/summary_reading.h"

#include "core/common/nan.h"
#include "core/processing/measures.h"

namespace lmc {

bool summary_has_vicon(const nlohmann::json& summary) {
  return summary.contains("vicon") && summary["vicon"].is_object();
}

double summary_element(const nlohmann::json& stats, const char* key, std::size_t k) {
  if (!stats.is_object() || !stats.contains(key) || !stats[key].is_array() || k >= stats[key].size()) return kNaN;
  const auto& v = stats[key][k];
  return v.is_number() ? v.get<double>() : kNaN;
}

std::vector<DeviceVisibility> summary_visibility(const nlohmann::json& summary) {
  std::vector<DeviceVisibility> out;
  if (!summary.contains("visibility") || !summary["visibility"].is_array()) return out;
  for (const auto& d : summary["visibility"]) {
    DeviceVisibility v;
    v.device = d.is_object() ? d.value("device", "?") : "?";
    for (std::size_t k = 0; k < static_cast<std::size_t>(kNumDigits); ++k)
      v.rates.push_back(summary_element(d, "rate", k));
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace lmc
