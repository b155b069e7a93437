#pragma once
// How a trial's summary JSON (core/processing/trial_summary.cpp) is read by the tables built from
// it: `lmc report` (session_report) and the Review tab's agreement tables (core/review) must agree
// on what counts as "has Vicon", a missing value and a visibility rate, so both read through here.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lmc {

// A trial has Vicon when its summary holds a "vicon" statistics object.
bool summary_has_vicon(const nlohmann::json& summary);

// stats[key][k] as a number. NaN when the key, the element or a number is missing: the summary
// writes a non-finite value as null, and null must never become 0.
double summary_element(const nlohmann::json& stats, const char* key, std::size_t k);

// One device's per-finger visibility rates as the summary lists them.
struct DeviceVisibility {
  std::string device;         // "LMC1" … ("?" when unnamed)
  std::vector<double> rates;  // five values; −1 ("never saw the hand") is kept, null → NaN
};

// The paper's visibility statistics keep −1 as a value (its 0.05 ± 0.55 mixes −1 with rates in
// 0..1), so no rate is filtered here; the mean skips only NaN.
std::vector<DeviceVisibility> summary_visibility(const nlohmann::json& summary);

}  // namespace lmc
