#pragma once
// Frame sources by name, as the CLI and the workbench spell them:
//   "sim"          the simulated rig (also the default when no controller is attached)
//   "leapc"        Ultraleap controllers through LeapC (when built with the SDK)
//   "replay:FILE"  a recorded file played as live devices
#include <memory>
#include <string>
#include <vector>

#include "core/layout/layout.h"
#include "devices/frame_source.h"
#include "devices/sim/sim_config.h"
#include "devices/sim/sim_source.h"

namespace lmc::devices {

struct SourceSpec {
  std::string backend;      // "sim", "leapc", "replay"
  std::string replay_path;  // backend == "replay"
};
// Throws lmc::Error for an unknown backend or a missing replay file name.
SourceSpec parse_source_spec(const std::string& text);

// True when this build has the LeapC backend.
bool leapc_available();

struct SourceSettings {
  Layout layout;
  SimConfig sim;
  double speed = 1.0;       // sim / replay: 0 = as fast as possible
  double duration_s = 0.0;  // sim: stop after this much simulated time (0 = forever)
};
std::unique_ptr<FrameSource> make_source(const SourceSpec& spec, const SourceSettings& settings);

// Devices a backend reports right now (serial, backend, model), for `lmc devices`.
std::vector<DeviceInfo> list_devices(const SourceSpec& spec, const SourceSettings& settings);

}  // namespace lmc::devices
