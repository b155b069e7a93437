#pragma once
// Every parameter that changes what processing computes, as one JSON object: the key of the
// workbench's processing cache (a changed parameter must never reuse an old result) and the
// "parameters" of an export's sidecar (a figure says exactly how its numbers were made).
#include <nlohmann/json.hpp>

#include "core/processing/trial_pipeline.h"

namespace lmc {

nlohmann::json process_options_json(const ProcessOptions& options);

}  // namespace lmc
