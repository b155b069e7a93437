#pragma once
// Human- and machine-readable summaries of a Coverage (what `lmc evaluate` and `lmc optimize`
// print): M, the c_i histogram, the device × finger coverage table and "seen by nobody".
//
// JSON keys (coverage_to_json): "frames", "devices", "metric" (M), "c" (array c_0…c_D),
// "coverage" (array per device: {"slot", "thumb", "index", "middle", "ring", "pinky"} fractions
// of frames in which that device sees the finger), "unseen" ({"thumb": fraction, …} of frames
// in which no device sees it), "unseen_frames" (same as counts).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/metric/coverage.h"

namespace lmc {

// `slots` names the devices (LMC1…); missing names become "device N".
std::string format_coverage(const Coverage& coverage, const std::vector<std::string>& slots);
nlohmann::json coverage_to_json(const Coverage& coverage, const std::vector<std::string>& slots);

}  // namespace lmc
