#pragma once
// The recorder's settings as the recorder tests start from: a trial's files in `dir`, named after
// `trial`, for the paper's initial layout; each test then sets only what it is about.
#include <filesystem>
#include <string>

#include "core/io/layout_json.h"
#include "devices/record/recorder.h"
#include "tests/support/reference_data.h"

namespace lmc::test {

inline devices::RecorderConfig recorder_config(const std::filesystem::path& dir, const std::string& trial) {
  devices::RecorderConfig config;
  config.output_dir = dir;
  config.trial = trial;
  config.layout = load_layout(asset_file("layouts/paper-initial.json"));
  return config;
}

}  // namespace lmc::test
