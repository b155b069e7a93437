#pragma once
// The quality thresholds of a protocol file (its top-level "quality" and each trial type's) as
// JSON. Every key is optional and falls back to `defaults`, so a trial type only says where it
// differs; unknown keys are refused, naming the JSON path.
#include <nlohmann/json.hpp>

#include "core/io/json_checked.h"
#include "core/session/quality_thresholds.h"

namespace lmc {

QualityThresholds quality_thresholds_from_json(const JsonReader& r, const QualityThresholds& defaults);
nlohmann::json quality_thresholds_to_json(const QualityThresholds& q);

}  // namespace lmc
