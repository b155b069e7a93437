#pragma once
// Frame sources by name, as the CLI and the workbench spell them:
//   "sim"          the simulated rig (also the default when no controller is attached)
//   "leapc"        Ultraleap controllers through LeapC (the library is found when it starts)
//   "replay:FILE"  a recorded file played as live devices
#include <cstdint>
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

// True when this build has the LeapC backend (always: whether Ultraleap's library is installed is
// found out when the backend starts, see devices/leapc/leapc_library.h).
bool leapc_available();

struct SourceSettings {
  Layout layout;
  SimConfig sim;
  double speed = 1.0;                                 // sim / replay: 0 = as fast as possible
  double duration_s = 0.0;                            // sim: stop after this much simulated time (0 = forever)
  std::uint32_t leapc_wait_ms = 1500;                 // list_devices, leapc: how long to listen
  std::vector<std::string>* leapc_notices = nullptr;  // list_devices, leapc: the backend's messages
};
std::unique_ptr<FrameSource> make_source(const SourceSpec& spec, const SourceSettings& settings);

// Devices a backend reports right now (serial, backend, model), for `lmc devices`.
std::vector<DeviceInfo> list_devices(const SourceSpec& spec, const SourceSettings& settings);

}  // namespace lmc::devices
