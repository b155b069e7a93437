#include "devices/source_factory.h"

#include "core/common/error.h"
#include "devices/leapc/leapc_source.h"
#include "devices/replay/replay_source.h"
#include "devices/sim/sim_rig.h"

namespace lmc::devices {

SourceSpec parse_source_spec(const std::string& text) {
  if (text == "sim" || text == "leapc") return {text, {}};
  if (text.rfind("replay:", 0) == 0) {
    SourceSpec s{"replay", text.substr(7)};
    if (s.replay_path.empty()) throw Error("--backend replay: needs a file, e.g. replay:LMC_trial.raw.txt");
    return s;
  }
  throw Error("unknown backend '" + text + "': use sim, leapc or replay:FILE");
}

bool leapc_available() {
  return true;  // always built: the library is looked for when the backend starts
}

std::unique_ptr<FrameSource> make_source(const SourceSpec& spec, const SourceSettings& s) {
  if (spec.backend == "sim")
    return std::make_unique<SimSource>(s.layout, s.sim, SimSourceOptions{s.speed, s.duration_s});
  if (spec.backend == "replay") {
    ReplayOptions o;
    o.speed = s.speed;
    return std::make_unique<ReplaySource>(spec.replay_path, o);
  }
  if (spec.backend == "leapc") {
    LeapcOptions options;
    options.layout = s.layout;  // each controller's tracking mode follows its slot's pose
    return std::make_unique<LeapcSource>(options);
  }
  throw Error("unknown backend '" + spec.backend + "'");
}

std::vector<DeviceInfo> list_devices(const SourceSpec& spec, const SourceSettings& s) {
  if (spec.backend == "sim") return SimRig(s.layout, s.sim).devices();
  if (spec.backend == "replay") return ReplaySource(spec.replay_path).devices();
  if (spec.backend == "leapc") return leapc_list_devices(s.leapc_wait_ms, s.leapc_notices);
  throw Error("unknown backend '" + spec.backend + "'");
}

}  // namespace lmc::devices
