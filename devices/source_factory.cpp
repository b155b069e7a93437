#include "devices/source_factory.h"

#include "core/common/error.h"
#include "devices/replay/replay_source.h"
#include "devices/sim/sim_rig.h"
#if LMC_HAVE_LEAPC
#include "devices/leapc/leapc_source.h"
#endif

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
#if LMC_HAVE_LEAPC
  return true;
#else
  return false;
#endif
}

namespace {
[[noreturn]] void no_leapc() {
  throw Error(
      "this build has no LeapC backend: the Ultraleap SDK was not found at configure time "
      "(install it as devices/leapc/README.md describes, then re-run CMake); use --backend sim meanwhile");
}
}  // namespace

std::unique_ptr<FrameSource> make_source(const SourceSpec& spec, const SourceSettings& s) {
  if (spec.backend == "sim")
    return std::make_unique<SimSource>(s.layout, s.sim, SimSourceOptions{s.speed, s.duration_s});
  if (spec.backend == "replay") {
    ReplayOptions o;
    o.speed = s.speed;
    return std::make_unique<ReplaySource>(spec.replay_path, o);
  }
  if (spec.backend == "leapc") {
#if LMC_HAVE_LEAPC
    LeapcOptions options;
    options.layout = s.layout;  // each controller's tracking mode follows its slot's pose
    return std::make_unique<LeapcSource>(options);
#else
    no_leapc();
#endif
  }
  throw Error("unknown backend '" + spec.backend + "'");
}

std::vector<DeviceInfo> list_devices(const SourceSpec& spec, const SourceSettings& s) {
  if (spec.backend == "sim") return SimRig(s.layout, s.sim).devices();
  if (spec.backend == "replay") return ReplaySource(spec.replay_path).devices();
#if LMC_HAVE_LEAPC
  if (spec.backend == "leapc") return leapc_list_devices();
#else
  if (spec.backend == "leapc") no_leapc();
#endif
  throw Error("unknown backend '" + spec.backend + "'");
}

}  // namespace lmc::devices
