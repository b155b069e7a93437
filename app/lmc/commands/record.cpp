// lmc record --backend sim|leapc|replay:FILE --layout L --trial NAME --seconds S [--motion M]
//            [--vicon HOST[:PORT]] -o DIR
// Records one trial headless: every frame of every device to DIR/LMC_<trial>.raw.txt (the study's
// raw format), a sidecar DIR/LMC_<trial>.session.json and, for the simulator, the ground truth as
// DIR/<trial>.trc (26 Vicon markers, 100 Hz). Layout of the folder: sessions/README.md.
// While recording, stderr shows one status line per second (per-device rate, hand present,
// frames written); device messages (disconnects, failures) are printed as they happen; stdout
// gets a summary. With --vicon the Vicon capture trigger (CaptureStart when every device streams,
// CaptureStop at the end, each sent --vicon-repeats times) goes to HOST:PORT. --fast runs the
// simulator in simulated time, faster than real time. --vicon-listen PORT instead waits for
// Vicon's own CaptureStart (its Name becomes the trial name unless --trial is given) and records
// until CaptureStop; --vicon-host names the Vicon PC(s) whose messages are obeyed (others are
// refused, said on stderr and counted in the sidecar) and, without --vicon-listen-address, picks
// the interface that reaches them. Ctrl-C stops the trial cleanly. At CaptureStart (sent or received) every
// device's latest frame goes into the sidecar's "vicon_alignment" (devices/README.md). A trial
// ended by an error (Vicon refused, a device never streamed) keeps its rows and its sidecar says
// "aborted" with the error; a write error (disk full, `ulimit -f`) says "failed". The trial itself
// runs in devices/record/trial_engine.h; this file turns options into its config and its
// snapshots into stderr lines.
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stop_token>
#include <string>

#include "app/lmc/command.h"
#include "app/lmc/sigint_flag.h"
#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "devices/device_hub.h"
#include "devices/record/recorder.h"
#include "devices/record/trial_engine.h"
#include "devices/record/trial_name.h"
#include "devices/sim/sim_source.h"
#include "devices/source_factory.h"
#include "devices/vicon/vicon_trigger.h"

namespace {

using namespace lmc::devices;

struct RecordOptions {
  std::string backend = "sim";
  std::string layout = "paper-initial";
  std::string trial;
  double seconds = 5.0;
  std::string motion;
  std::string vicon;
  int vicon_repeats = 3;
  std::string vicon_database;
  std::string vicon_notes;
  std::string vicon_description;
  std::string sim_config;
  long long seed = -1;
  bool fast = false;
  double speed = 1.0;
  double stream_timeout_s = 10.0;
  int vicon_listen_port = 0;
  std::string vicon_listen_address;  // empty: the interface towards --vicon-host, else every one
  std::string vicon_hosts;
  std::string out_dir;
  bool force = false;
  bool quiet = false;
};

std::string record_status_line(const HubSnapshot& snap, const RecorderStatus& rec, double elapsed_s) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << std::setw(6) << elapsed_s << " s ";
  for (const auto& d : snap.devices) {
    if (d.slot.empty()) continue;
    s << " | " << d.slot << ' ' << std::setprecision(0) << std::setw(3) << d.rate_hz << " Hz "
      << (!d.connected     ? "LOST"
          : d.hand_present ? "hand"
                           : "----");
    auto it = rec.devices.find(d.slot_index + 1);
    s << ' ' << (it == rec.devices.end() ? 0 : it->second.frames_written);
  }
  s << " | written " << rec.frames_written;
  if (rec.frames_dropped > 0) s << " dropped " << rec.frames_dropped;
  return s.str();
}

// Device messages go to stderr as they happen; --quiet keeps only the ones that need attention,
// leaving out the routine notes that a controller connected or was assigned its slot.
bool is_connection_note(const std::string& m) {
  return m.find(" connected (") != std::string::npos || m.find(" assigned to ") != std::string::npos;
}

// The options as a trial for the engine (devices/record/trial_engine.h), which runs it.
TrialEngineConfig engine_config(const RecordOptions& opt, const SourceSpec& spec, const SourceSettings& settings) {
  TrialEngineConfig c;
  c.output_dir = opt.out_dir;
  c.trial = opt.trial;
  c.seconds = opt.seconds;
  c.stream_timeout_s = opt.stream_timeout_s;
  c.backend = spec.backend;
  c.allow_overwrite = opt.force;
  c.stopped_by = "operator (Ctrl-C)";
  if (spec.backend == "sim") c.extra["simulator"] = sim_config_to_json(settings.sim);
  if (spec.backend == "replay") c.extra["replay_of"] = spec.replay_path;
  if (!opt.vicon.empty()) {
    ViconTriggerConfig vc = parse_vicon_target(opt.vicon);
    vc.repeats = opt.vicon_repeats;
    vc.database_path = opt.vicon_database;
    vc.notes = opt.vicon_notes;
    vc.description = opt.vicon_description;
    c.vicon = vc;
  }
  if (opt.vicon_listen_port > 0) {
    c.vicon_listen = std::make_pair(opt.vicon_listen_address, static_cast<std::uint16_t>(opt.vicon_listen_port));
    c.vicon_senders = ViconSenders::parse(opt.vicon_hosts);
  }
  return c;
}

void print_summary(const TrialResult& r, const HubSnapshot& snap, const std::string& backend, const std::string& layout,
                   double truth_rate_hz) {
  const RecorderStatus& st = r.recorder;
  std::cout << "trial " << r.trial << ": " << st.frames_written << " frames from " << st.devices.size() << " devices ("
            << backend << ", layout " << layout << ")\n";
  for (const auto& [id, d] : st.devices) {
    const double span_s = static_cast<double>(d.last_timestamp_us - d.first_timestamp_us) / 1e6;
    std::cout << "  " << std::left << std::setw(6) << d.slot << std::setw(22) << d.serial << std::right << std::setw(7)
              << d.frames_written << " frames";
    if (span_s > 0)
      std::cout << std::fixed << std::setprecision(1) << std::setw(7)
                << static_cast<double>(d.frames_written - 1) / span_s << " Hz";
    if (d.frames_written > 0) std::cout << std::setw(5) << (100 * d.frames_with_hand / d.frames_written) << "% hand";
    if (!d.gaps.empty()) std::cout << "  " << d.gaps.size() << " gap(s)";
    if (!d.disconnects.empty()) std::cout << "  " << d.disconnects.size() << " disconnect(s)";
    if (d.frames_dropped_queue > 0) std::cout << "  " << d.frames_dropped_queue << " dropped";
    std::cout << "\n";
  }
  for (const auto& s : snap.unassigned_serials) std::cout << "  unassigned device " << s << " (not recorded)\n";
  std::cout << "  recording: " << r.paths.recording.string() << "\n  sidecar:   " << r.paths.sidecar.string() << "\n";
  if (!r.listen_address.empty()) {
    std::cout << "  vicon:     "
              << (r.vicon_trigger_host.empty() ? "no CaptureStart obeyed" : "CaptureStart from " + r.vicon_trigger_host)
              << " (listening on " << r.listen_address << ")";
    if (r.vicon_refused > 0) std::cout << "; " << r.vicon_refused << " datagram(s) from other hosts refused";
    std::cout << "\n";
  }
  if (r.truth_seconds > 0 && std::filesystem::exists(r.paths.truth_trc))
    std::cout << "  truth:     " << r.paths.truth_trc.string() << " (" << r.truth_seconds << " s at " << truth_rate_hz
              << " Hz)\n";
}

void run_record(const RecordOptions& opt) {
  const bool listen = opt.vicon_listen_port > 0;
  if (!listen || !opt.trial.empty()) require_valid_trial_name(opt.trial);
  if (!(opt.seconds > 0)) throw lmc::Error("--seconds must be > 0");
  const SourceSpec spec = parse_source_spec(opt.backend);
  if (opt.fast && spec.backend == "leapc") throw lmc::Error("--fast applies to sim and replay only");
  if (opt.fast && listen) throw lmc::Error("--fast and --vicon-listen exclude each other (Vicon runs in real time)");
  if (!listen && (!opt.vicon_hosts.empty() || !opt.vicon_listen_address.empty()))
    throw lmc::Error(
        "--vicon-host and --vicon-listen-address apply to --vicon-listen (who may trigger, where to listen)");

  SourceSettings settings;
  settings.layout = lmc::load_layout_or_preset(opt.layout);
  if (!opt.sim_config.empty()) settings.sim = load_sim_config(opt.sim_config);
  if (opt.seed >= 0) settings.sim.seed = static_cast<std::uint64_t>(opt.seed);
  if (!opt.motion.empty()) apply_motion_spec(settings.sim, opt.motion);
  settings.speed = opt.fast ? 0.0 : opt.speed;
  // In listen mode the trial starts whenever Vicon says so: the simulator runs until stopped.
  settings.duration_s = spec.backend == "sim" && !listen ? opt.seconds : 0.0;

  const TrialEngineConfig config = engine_config(opt, spec, settings);
  HubOptions hub_options;
  hub_options.backpressure = opt.fast;
  DeviceHub hub(settings.layout, hub_options);
  std::unique_ptr<FrameSource> source = make_source(spec, settings);
  auto* sim = dynamic_cast<SimSource*>(source.get());
  hub.add_source(std::move(source));

  // Ctrl-C only sets a flag (all a signal handler may do); the status callback turns it into
  // the engine's stop request.
  std::stop_source stop;
  std::optional<lmc::cli::ScopedSigint> sigint(std::in_place);
  double last_status = -1;
  auto on_status = [&](const TrialSnapshot& s) {
    for (const auto& m : s.new_notices)
      if (!opt.quiet) std::cerr << "lmc record: " << m << "\n";
    for (const auto& m : s.new_messages)
      if (!opt.quiet || !is_connection_note(m)) std::cerr << "lmc record: " << m << "\n";
    if (lmc::cli::sigint_raised() && !stop.stop_requested()) {
      std::cerr << "\nlmc record: interrupted; stopping the trial\n";
      stop.request_stop();
    }
    const bool live = s.phase != TrialPhase::kFinishing && s.phase != TrialPhase::kDone;
    if (!opt.quiet && live && s.elapsed_s - last_status >= 1.0) {
      last_status = s.elapsed_s;
      std::cerr << record_status_line(s.hub, s.recorder, s.elapsed_s) << "\n";
    }
  };
  TrialEngine engine(hub, sim, config);
  const TrialResult result = engine.run(stop.get_token(), on_status);
  sigint.reset();

  if (!result.existing.empty())
    throw lmc::Error(result.existing.string() + " exists; choose another trial name or pass --force");
  if (!result.recorded) throw lmc::Error(result.reason);
  print_summary(result, hub.snapshot(), spec.backend, settings.layout.name,
                sim != nullptr ? sim->rig().config().truth_rate_hz : 0.0);
  if (result.outcome == TrialOutcome::kAborted || result.outcome == TrialOutcome::kFailed) {
    std::string failure = result.reason;
    if (failure.find("kept") == std::string::npos) failure += " (the rows written so far are kept)";
    throw lmc::Error(failure);
  }
}

void setup_record(CLI::App& app) {
  auto opt = std::make_shared<RecordOptions>();
  app.add_option("--backend", opt->backend, "sim, leapc or replay:FILE")->capture_default_str();
  app.add_option("--layout", opt->layout, "Layout file or preset name")->capture_default_str();
  app.add_option("--trial", opt->trial,
                 "Trial name: letters, digits, _ and -; names the files (with --vicon-listen: default Vicon's Name)");
  app.add_option("--seconds", opt->seconds, "Trial length (simulated seconds with --fast)")->capture_default_str();
  app.add_option("--motion", opt->motion,
                 "Simulator motion: static, index, thumb, wrist (prefix horizontal/ or vertical/), or a pose-set file");
  app.add_option("--vicon", opt->vicon, "Send the Vicon UDP capture trigger to HOST[:PORT] (port 30 by default)");
  app.add_option("--vicon-repeats", opt->vicon_repeats, "Send each trigger packet this many times")
      ->capture_default_str();
  app.add_option("--vicon-database", opt->vicon_database, "DatabasePath field of the trigger");
  app.add_option("--vicon-notes", opt->vicon_notes, "Notes field of CaptureStart");
  app.add_option("--vicon-description", opt->vicon_description, "Description field of CaptureStart");
  app.add_option("--vicon-listen", opt->vicon_listen_port,
                 "Wait for a Vicon CaptureStart on this UDP port, record until CaptureStop (or --seconds)");
  app.add_option("--vicon-host", opt->vicon_hosts,
                 "With --vicon-listen: obey only these senders: IPv4 addresses, subnets (10.0.0.0/24) or host names, "
                 "comma-separated (default: any sender, with a warning)");
  app.add_option("--vicon-listen-address", opt->vicon_listen_address,
                 "Address to listen on (default: the interface that reaches --vicon-host, else every interface)");
  app.add_option("--sim-config", opt->sim_config, "Simulator settings (JSON; every behaviour switchable)");
  app.add_option("--seed", opt->seed, "Simulator seed (overrides --sim-config)");
  app.add_flag("--fast", opt->fast, "Simulated time: run the simulator (or a replay) as fast as possible");
  app.add_option("--speed", opt->speed, "Replay / simulator speed factor in real-time mode")->capture_default_str();
  app.add_option("--stream-timeout", opt->stream_timeout_s, "Give up when not every device streams within this many s")
      ->capture_default_str();
  app.add_option("-o,--output", opt->out_dir, "Session folder (created if missing)")->required();
  app.add_flag("--force", opt->force, "Overwrite an existing trial of the same name");
  app.add_flag("--quiet", opt->quiet, "No live status line");
  app.callback([opt] { run_record(*opt); });
}

const lmc::cli::CommandRegistration record_command{"record", "Record a trial from the devices (headless)", 21,
                                                   setup_record};

}  // namespace
