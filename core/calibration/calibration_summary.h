#pragma once
// A calibration's result as JSON for the record (a session's journal and manifest):
// per controller whether it was fitted, the correction, RMS residual before and after, its
// warnings; for the set the disagreement between controllers and every set-level warning.
//   {"with_vicon": bool, "disagreement_before_mm": x, "disagreement_after_mm": x, "warnings": [..],
//    "devices": [{"slot", "fitted", "samples", "rms_before_mm", "rms_after_mm", "moved_mm",
//                 "turned_deg", "warnings": [..]}]}
// NaN (no samples) is written as null.
#include <nlohmann/json.hpp>

#include "core/calibration/calibration_result.h"

namespace lmc {

nlohmann::json calibration_summary_json(const CalibrationResult& result);

}  // namespace lmc
