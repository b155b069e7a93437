#pragma once
// The machine-readable summary of one processed trial (the `<trial>.summary.json` that `lmc
// process` writes, and what the session table and the Review tab read): per-trial statistics of
// LMC and Vicon, visibility per controller, the resampler's report per stream and the comparison.
// Values that are not finite are null, never 0.
#include <nlohmann/json.hpp>

#include "core/processing/trial_pipeline.h"

namespace lmc {

nlohmann::json trial_summary_json(const TrialAnalysis& r);

}  // namespace lmc
