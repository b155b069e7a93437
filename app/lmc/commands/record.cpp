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
// until CaptureStop. Ctrl-C stops the trial cleanly. At CaptureStart (sent or received) every
// device's latest frame goes into the sidecar's "vicon_alignment" (devices/README.md). A trial
// ended by an error (Vicon refused, a device never streamed) keeps its rows and its sidecar says
// "aborted" with the error; a write error (disk full, `ulimit -f`) says "failed".
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <cmath>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "core/io/trc.h"
#include "devices/device_hub.h"
#include "devices/host_clock.h"
#include "devices/record/clock_alignment.h"
#include "devices/record/recorder.h"
#include "devices/record/trial_name.h"
#include "devices/sim/sim_source.h"
#include "devices/source_factory.h"
#include "devices/vicon/vicon_trigger.h"

namespace {

using namespace lmc::devices;

std::atomic<bool> g_interrupted{false};
extern "C" void on_sigint(int) { g_interrupted = true; }

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
  std::string vicon_listen_address = "0.0.0.0";
  std::string out_dir;
  bool force = false;
  bool quiet = false;
};

std::string status_line(const HubSnapshot& snap, const RecorderStatus& rec, double elapsed_s) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << std::setw(6) << elapsed_s << " s ";
  for (const auto& d : snap.devices) {
    if (d.slot.empty()) continue;
    s << " | " << d.slot << ' ' << std::setprecision(0) << std::setw(3) << d.rate_hz << " Hz "
      << (!d.connected ? "LOST" : d.hand_present ? "hand" : "----");
    auto it = rec.devices.find(d.slot_index + 1);
    s << ' ' << (it == rec.devices.end() ? 0 : it->second.frames_written);
  }
  s << " | written " << rec.frames_written;
  if (rec.frames_dropped > 0) s << " dropped " << rec.frames_dropped;
  return s.str();
}

// Device messages go to stderr as they happen; --quiet keeps only the ones that need attention.
void print_messages(DeviceHub& hub, bool quiet) {
  for (const auto& m : hub.take_messages()) {
    const bool routine = m.find(" connected (") != std::string::npos || m.find(" assigned to ") != std::string::npos;
    if (!quiet || !routine) std::cerr << "lmc record: " << m << "\n";
  }
}

void run_record(const RecordOptions& opt) {
  const bool listen = opt.vicon_listen_port > 0;
  if (!listen || !opt.trial.empty()) require_valid_trial_name(opt.trial);
  if (!(opt.seconds > 0)) throw lmc::Error("--seconds must be > 0");
  const SourceSpec spec = parse_source_spec(opt.backend);
  if (opt.fast && spec.backend == "leapc") throw lmc::Error("--fast applies to sim and replay only");
  if (opt.fast && listen) throw lmc::Error("--fast and --vicon-listen exclude each other (Vicon runs in real time)");

  SourceSettings settings;
  settings.layout = lmc::load_layout_or_preset(opt.layout);
  if (!opt.sim_config.empty()) settings.sim = load_sim_config(opt.sim_config);
  if (opt.seed >= 0) settings.sim.seed = static_cast<std::uint64_t>(opt.seed);
  if (!opt.motion.empty()) apply_motion_spec(settings.sim, opt.motion);
  settings.speed = opt.fast ? 0.0 : opt.speed;
  // In listen mode the trial starts whenever Vicon says so: the simulator runs until stopped.
  settings.duration_s = spec.backend == "sim" && !listen ? opt.seconds : 0.0;

  auto check_free = [&](const std::string& trial) {
    const SessionPaths paths = session_paths(opt.out_dir, trial);
    if (!opt.force)
      for (const auto& p : {paths.recording, paths.sidecar, paths.truth_trc})
        if (std::filesystem::exists(p)) throw lmc::Error(p.string() + " exists; choose another trial name or pass --force");
    return paths;
  };
  std::string trial = opt.trial;
  SessionPaths paths;
  if (!trial.empty()) paths = check_free(trial);

  std::unique_ptr<ViconTrigger> vicon;
  if (!opt.vicon.empty()) {
    ViconTriggerConfig vc = parse_vicon_target(opt.vicon);
    vc.repeats = opt.vicon_repeats;
    vc.database_path = opt.vicon_database;
    vc.notes = opt.vicon_notes;
    vc.description = opt.vicon_description;
    vicon = std::make_unique<ViconTrigger>(vc);
  }
  // Vicon's own start/stop broadcasts (or another lab program's) drive the trial.
  std::mutex vicon_in_mutex;
  std::vector<std::pair<ViconMessage, std::int64_t>> vicon_in;  // with the host time it arrived
  std::unique_ptr<ViconListener> listener;
  if (listen) {
    listener = std::make_unique<ViconListener>(opt.vicon_listen_address, static_cast<std::uint16_t>(opt.vicon_listen_port),
                                               [&](const ViconMessage& m) {
                                                 const std::int64_t at = host_now_ns();
                                                 std::lock_guard lock(vicon_in_mutex);
                                                 vicon_in.emplace_back(m, at);
                                               });
    if (!opt.quiet)
      std::cerr << "lmc record: waiting for CaptureStart on " << opt.vicon_listen_address << ":" << listener->port() << "\n";
  }

  HubOptions hub_options;
  hub_options.backpressure = opt.fast;
  DeviceHub hub(settings.layout, hub_options);
  std::unique_ptr<FrameSource> source = make_source(spec, settings);
  auto* sim = dynamic_cast<SimSource*>(source.get());
  hub.add_source(std::move(source));

  std::unique_ptr<Recorder> recorder;
  double sim_time_at_start = 0;
  auto begin_recording = [&] {
    RecorderConfig rc;
    rc.output_dir = opt.out_dir;
    rc.trial = trial;
    rc.layout = settings.layout;
    rc.backend = spec.backend;
    if (spec.backend == "sim") rc.extra["simulator"] = sim_config_to_json(settings.sim);
    if (spec.backend == "replay") rc.extra["replay_of"] = spec.replay_path;
    recorder = std::make_unique<Recorder>(rc);
    recorder->start();
    if (sim != nullptr) sim_time_at_start = sim->simulated_time_s();
    hub.set_consumer(recorder.get());
  };
  if (!listen) begin_recording();

  g_interrupted = false;
  auto previous = std::signal(SIGINT, on_sigint);
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  hub.start();

  // Vicon starts when every slot streams (the study's rule), so both files cover the same span.
  auto all_streaming = [&] {
    const auto snap = hub.snapshot();
    int streaming = 0;
    for (const auto& d : snap.devices) streaming += (d.slot_index >= 0 && d.frames_received > 0) ? 1 : 0;
    return streaming >= settings.layout.device_count();
  };
  std::string failure;
  bool vicon_started = false;
  auto send_vicon = [&](bool start) {
    if (!vicon) return;
    // Every device's latest frame just before CaptureStart leaves: with the send time it ties
    // each device clock to the instant Vicon starts (sidecar "vicon_alignment").
    const HubSnapshot before = hub.snapshot();
    const ViconSendResult r = start ? vicon->send_start(trial) : vicon->send_stop(trial);
    if (start && recorder && r.datagrams_sent > 0)
      recorder->note("vicon_alignment", clock_alignment_json(before, "CaptureStart sent", r.first_datagram_host_ns,
                                                             r.message.packet_id, utc_now_iso8601()));
    nlohmann::json p = {{"type", start ? "CaptureStart" : "CaptureStop"},
                        {"packet_id", r.message.packet_id},
                        {"target", vicon->target()},
                        {"datagrams_sent", r.datagrams_sent},
                        {"host_time_utc", utc_now_iso8601()},
                        {"host_ns", host_now_ns()}};
    if (!r.ok()) p["error"] = r.error;
    if (!r.warning.empty()) {
      p["warning"] = r.warning;
      std::cerr << "lmc record: " << r.warning << "\n";
    }
    if (recorder) recorder->note_vicon_packet(p);
    if (!r.ok()) {
      std::cerr << "lmc record: " << r.error << "\n";
      if (failure.empty()) failure = r.error;
    } else if (!opt.quiet) {
      std::cerr << "lmc record: Vicon " << (start ? "CaptureStart" : "CaptureStop") << " sent to " << vicon->target()
                << " (PacketID " << r.message.packet_id << ", " << r.datagrams_sent << "×)\n";
    }
  };

  double record_start_s = -1;
  double last_status = -1;
  bool stop_from_vicon = false;
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(opt.fast ? 20 : 50));
    print_messages(hub, opt.quiet);
    const double now = elapsed();
    if (listen) {
      std::vector<std::pair<ViconMessage, std::int64_t>> got;
      {
        std::lock_guard lock(vicon_in_mutex);
        got.swap(vicon_in);
      }
      for (const auto& [m, received_ns] : got) {
        if (m.type == ViconMessage::Type::kStart && !recorder) {
          if (opt.trial.empty()) {
            if (auto why = validate_trial_name(m.name); !why.empty()) {
              std::cerr << "lmc record: ignoring CaptureStart: its Name cannot be a trial name (" << why << ")\n";
              continue;
            }
            trial = m.name;
            try {
              paths = check_free(trial);
            } catch (const std::exception& e) {
              failure = e.what();
              break;
            }
          }
          begin_recording();
          recorder->note("vicon_alignment", clock_alignment_json(hub.snapshot(), "CaptureStart received", received_ns,
                                                                 m.packet_id, utc_now_iso8601()));
          recorder->note("vicon_trigger_received", {{"type", "CaptureStart"}, {"name", m.name}, {"packet_id", m.packet_id},
                                                    {"host_time_utc", utc_now_iso8601()}});
          record_start_s = now;
          if (!opt.quiet) std::cerr << "lmc record: CaptureStart received: recording " << trial << "\n";
        } else if (m.type == ViconMessage::Type::kStop && recorder) {
          recorder->note("vicon_stop_received", {{"name", m.name}, {"packet_id", m.packet_id}, {"result", m.result},
                                                 {"host_time_utc", utc_now_iso8601()}});
          stop_from_vicon = true;
        }
      }
      if (!failure.empty() || stop_from_vicon) break;
    } else if (record_start_s < 0) {
      if (all_streaming() || hub.sources_finished()) {
        record_start_s = now;
        send_vicon(true);
        vicon_started = vicon != nullptr;
      } else if (now > opt.stream_timeout_s) {
        failure = "not every device of layout '" + settings.layout.name + "' streamed within " +
                  std::to_string(static_cast<int>(opt.stream_timeout_s)) + " s";
        break;
      }
    }
    if (recorder && recorder->failed()) {
      failure = recorder->status().error;
      break;
    }
    if (g_interrupted) {
      std::cerr << "\nlmc record: interrupted; stopping the trial\n";
      if (recorder) recorder->note("stopped_by", "operator (Ctrl-C)");
      break;
    }
    if (!opt.quiet && now - last_status >= 1.0) {
      last_status = now;
      std::cerr << status_line(hub.snapshot(), recorder ? recorder->status() : RecorderStatus{}, now) << "\n";
    }
    if (hub.sources_finished()) break;
    const bool timed = listen || (!opt.fast && spec.backend != "sim");
    if (timed && record_start_s >= 0 && now - record_start_s >= opt.seconds) break;
    if (!failure.empty()) break;
  }
  hub.stop();
  hub.set_consumer(nullptr);
  print_messages(hub, opt.quiet);
  std::signal(SIGINT, previous);
  listener.reset();
  if (vicon_started) send_vicon(false);
  if (!recorder) throw lmc::Error(failure.empty() ? "no CaptureStart received; nothing recorded" : failure);

  double truth_from = 0, truth_seconds = 0;
  if (sim != nullptr) {
    truth_from = sim_time_at_start;
    truth_seconds = (sim->finished() ? opt.seconds : sim->simulated_time_s()) - truth_from;
    auto truth = sim->truth_until(truth_from + truth_seconds);
    const auto skip = static_cast<size_t>(std::ceil(truth_from * settings.sim.truth_rate_hz - 1e-9));
    truth.erase(truth.begin(), truth.begin() + static_cast<std::ptrdiff_t>(std::min(skip, truth.size())));
    lmc::TrcData trc = truth_trc(truth, settings.sim.truth_rate_hz, sim->rig().marker_map());
    const double first_s = static_cast<double>(skip) / settings.sim.truth_rate_hz;
    try {
      lmc::save_trc(paths.truth_trc, trc);
      recorder->note("ground_truth",
                     {{"file", paths.truth_trc.filename().string()},
                      {"rate_hz", settings.sim.truth_rate_hz},
                      {"frames", trc.frame_count()},
                      {"device_clock_at_time_zero_us",
                       settings.sim.device_clock_start_us + static_cast<std::int64_t>(std::llround(first_s * 1e6))},
                      {"mapping", "assets/mappings/vicon-26-to-lmc.json (exact inverse)"}});
    } catch (const std::exception& e) {
      if (failure.empty()) failure = std::string("cannot write the ground truth: ") + e.what();
    }
  }
  // An abort (Vicon refused the trigger, a device never streamed, …) makes the sidecar say
  // "aborted" with the reason; a write error of the recorder's own stays "failed".
  const RecorderStatus st = recorder->stop(hub.serial_to_slot(), failure);
  if (failure.empty() && (st.state == RecorderState::kFailed || st.state == RecorderState::kAborted)) failure = st.error;

  const HubSnapshot snap = hub.snapshot();
  std::cout << "trial " << trial << ": " << st.frames_written << " frames from " << st.devices.size()
            << " devices (" << spec.backend << ", layout " << settings.layout.name << ")\n";
  for (const auto& [id, d] : st.devices) {
    const double span_s = static_cast<double>(d.last_timestamp_us - d.first_timestamp_us) / 1e6;
    std::cout << "  " << std::left << std::setw(6) << d.slot << std::setw(22) << d.serial << std::right << std::setw(7)
              << d.frames_written << " frames";
    if (span_s > 0)
      std::cout << std::fixed << std::setprecision(1) << std::setw(7)
                << static_cast<double>(d.frames_written - 1) / span_s << " Hz";
    if (d.frames_written > 0)
      std::cout << std::setw(5) << (100 * d.frames_with_hand / d.frames_written) << "% hand";
    if (!d.gaps.empty()) std::cout << "  " << d.gaps.size() << " gap(s)";
    if (!d.disconnects.empty()) std::cout << "  " << d.disconnects.size() << " disconnect(s)";
    if (d.frames_dropped_queue > 0) std::cout << "  " << d.frames_dropped_queue << " dropped";
    std::cout << "\n";
  }
  for (const auto& s : snap.unassigned_serials) std::cout << "  unassigned device " << s << " (not recorded)\n";
  std::cout << "  recording: " << paths.recording.string() << "\n  sidecar:   " << paths.sidecar.string() << "\n";
  if (sim != nullptr && std::filesystem::exists(paths.truth_trc))
    std::cout << "  truth:     " << paths.truth_trc.string() << " (" << truth_seconds << " s at "
              << settings.sim.truth_rate_hz << " Hz)\n";
  if (!failure.empty()) {
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
  app.add_option("--vicon-repeats", opt->vicon_repeats, "Send each trigger packet this many times")->capture_default_str();
  app.add_option("--vicon-database", opt->vicon_database, "DatabasePath field of the trigger");
  app.add_option("--vicon-notes", opt->vicon_notes, "Notes field of CaptureStart");
  app.add_option("--vicon-description", opt->vicon_description, "Description field of CaptureStart");
  app.add_option("--vicon-listen", opt->vicon_listen_port,
                 "Wait for a Vicon CaptureStart on this UDP port, record until CaptureStop (or --seconds)");
  app.add_option("--vicon-listen-address", opt->vicon_listen_address, "Address to listen on")->capture_default_str();
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

const lmc::cli::CommandRegistration reg{"record", "Record a trial from the devices (headless)", 21, setup_record};

}  // namespace
