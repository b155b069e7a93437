#pragma once
// What the simulator's tests share: the paper's initial layout, and a simulator with every error
// source off, so that a controller's realigned frame is exactly the hand it models.
#include "core/io/layout_json.h"
#include "devices/sim/sim_config.h"
#include "tests/support/reference_data.h"

namespace lmc::devices::sim_fixtures {

inline Layout paper_initial() {
  return load_layout(test::asset_file("layouts/paper-initial.json"));
}

inline SimConfig exact() {
  SimConfig c;
  c.noise = false;
  c.elbow_error = false;
  c.axis_cut = false;
  c.occlusion = false;
  return c;
}

}  // namespace lmc::devices::sim_fixtures
