#include "devices/record/trial_engine.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <sstream>
#include <thread>

#include "core/common/error.h"
#include "core/io/trc.h"
#include "devices/host_clock.h"
#include "devices/host_memory.h"
#include "devices/record/clock_alignment.h"
#include "devices/record/trial_name.h"
#include "devices/sim/truth_markers.h"
#include "devices/vicon/vicon_route.h"

namespace lmc::devices {

const char* trial_outcome_name(TrialOutcome o) {
  switch (o) {
    case TrialOutcome::kCompleted:
      return "completed";
    case TrialOutcome::kAborted:
      return "aborted";
    case TrialOutcome::kFailed:
      return "failed";
    case TrialOutcome::kInterrupted:
      return "interrupted";
  }
  return "?";
}

const char* trial_phase_name(TrialPhase p) {
  switch (p) {
    case TrialPhase::kWaitingForStreams:
      return "waiting_for_streams";
    case TrialPhase::kWaitingForVicon:
      return "waiting_for_vicon";
    case TrialPhase::kCountdown:
      return "countdown";
    case TrialPhase::kRecording:
      return "recording";
    case TrialPhase::kFinishing:
      return "finishing";
    case TrialPhase::kDone:
      return "done";
  }
  return "?";
}

// The state of one trial while it records (one run() call). Members are touched by the calling
// thread only, except `inbox`, which the Vicon listener's thread fills.
struct TrialEngine::TrialInProgress {
  using Clock = std::chrono::steady_clock;
  static constexpr auto kPoll = std::chrono::milliseconds(20);
  static constexpr auto kStatusEvery = std::chrono::milliseconds(100);
  // How long the end of a trial waits for every controller's stream to pass the window's end: a
  // controller at its slowest (11 Hz) sends its next frame within 0.1 s; a busy machine can hold a
  // device thread between stamping a frame and handing it on for a few hundred ms.
  static constexpr auto kStreamsPastEndLimit = std::chrono::milliseconds(1000);

  DeviceHub& hub;
  SimSource* sim;
  const TrialEngineConfig& cfg;
  std::stop_token stop;
  const std::function<void(const TrialSnapshot&)>& on_status;

  TrialResult result;
  TrialPhase phase = TrialPhase::kWaitingForStreams;
  std::string trial;
  std::string message;
  std::vector<std::string> pending_messages, pending_notices;
  std::unique_ptr<Recorder> recorder;
  std::unique_ptr<ViconTrigger> vicon;
  std::unique_ptr<ViconListener> listener;
  std::mutex inbox_mutex;
  int rejected_reported = 0;  // listener->rejected() already said
  struct Arrived {
    ViconMessage message;
    std::int64_t host_ns = 0;  // when it arrived
    ViconSender from;
  };
  std::vector<Arrived> inbox;
  std::string listen_binding;                 // how the listen address was chosen
  std::string listen_warning;                 // e.g. any sender is obeyed
  std::optional<ViconSender> trigger_sender;  // listen mode: who sent the CaptureStart obeyed
  Clock::time_point t0 = Clock::now();
  Clock::time_point last_report{};
  double sim_time_at_start = 0;                                         // simulated time at go (the truth starts there)
  double countdown_from = 0, recording_from = 0, recording_until = -1;  // engine clock
  // The simulator this engine starts decides go itself (its thread opens the recorder's window at
  // the first event of the trial), so a trial run faster than real time starts exactly at go.
  bool sim_decides_go = false;
  std::atomic<bool> went{false};
  bool recording_started = false;
  bool vicon_start_sent = false;
  bool vicon_stop_received = false;
  bool vicon_start_received = false;  // listen mode
  std::string vicon_start_name;       // listen mode: the Name of the CaptureStart that began the trial
  int vicon_sent = 0;
  bool interrupted = false;
  bool hub_started_here = false;
  std::string failure;  // first outside error: the trial ends "aborted" with it

  TrialInProgress(DeviceHub& h, SimSource* s, const TrialEngineConfig& c, std::stop_token st,
                  const std::function<void(const TrialSnapshot&)>& cb)
      : hub(h), sim(s), cfg(c), stop(std::move(st)), on_status(cb), trial(c.trial) {}

  bool listen() const { return cfg.vicon_listen.has_value(); }
  double wall_s() const { return std::chrono::duration<double>(Clock::now() - t0).count(); }
  // Simulated seconds with a simulator (a --fast trial is exact), else wall-clock seconds.
  double clock_s() const { return sim != nullptr ? sim->simulated_time_s() : wall_s(); }
  bool sim_decides_length() const { return sim != nullptr && sim->duration_s() > 0; }

  // Go: the recorder writes from `host_ns` on, for the planned length on the host clock when
  // `bounded` (any thread, once).
  void open_window(std::int64_t host_ns, bool bounded) {
    if (went.exchange(true)) return;
    recorder->open_window(host_ns, bounded ? host_ns + static_cast<std::int64_t>(std::llround(cfg.seconds * 1e9))
                                           : std::numeric_limits<std::int64_t>::max());
  }

  void say(std::string text) {
    result.messages.push_back(text);
    pending_messages.push_back(std::move(text));
  }
  void notice(std::string text) {
    result.messages.push_back(text);
    pending_notices.push_back(std::move(text));
  }
  void fail(const std::string& why) {
    if (failure.empty()) failure = why;
  }

  double recording_s() const {
    if (!recording_started) return 0;
    return std::max(0.0, (recording_until >= 0 ? recording_until : clock_s()) - recording_from);
  }

  void report(bool force) {
    for (auto& m : hub.take_messages()) say(std::move(m));
    const auto now = Clock::now();
    const bool news = !pending_messages.empty() || !pending_notices.empty();
    if (!on_status) {
      pending_messages.clear();
      pending_notices.clear();
      return;
    }
    if (!force && !news && now - last_report < kStatusEvery) return;
    last_report = now;
    TrialSnapshot s;
    s.phase = phase;
    s.trial = trial;
    s.elapsed_s = wall_s();
    if (phase == TrialPhase::kCountdown)
      s.countdown_remaining_s = std::max(0.0, cfg.countdown_s - (clock_s() - countdown_from));
    s.recording_s = recording_s();
    // A simulator that ends the trial itself ends it after its own duration from go.
    s.remaining_s = std::max(0.0, (sim_decides_length() ? sim->duration_s() : cfg.seconds) - s.recording_s);
    s.hub = hub.snapshot();
    if (recorder) s.recorder = recorder->status();
    s.vicon_packets_sent = vicon_sent;
    s.vicon_sending = cfg.vicon.has_value();
    s.vicon_listening = listen();
    s.vicon_listen_address = result.listen_address;
    s.vicon_trigger_host = trigger_sender ? trigger_sender->host() : std::string();
    s.vicon_refused = listener ? listener->refused() : 0;
    s.vicon_start_received = vicon_start_received;
    s.vicon_stop_received = vicon_stop_received;
    s.message = message;
    s.new_messages = std::move(pending_messages);
    s.new_notices = std::move(pending_notices);
    pending_messages.clear();
    pending_notices.clear();
    on_status(s);
  }

  void set_phase(TrialPhase p, std::string text) {
    phase = p;
    message = std::move(text);
    report(true);
  }

  void tick() {
    std::this_thread::sleep_for(kPoll);
    report(false);
  }

  // Vicon starts when every slot streams (the study's rule), so both files cover the same span.
  bool all_streaming() const {
    const HubSnapshot snap = hub.snapshot();
    size_t streaming = 0;
    for (const auto& d : snap.devices) streaming += (d.slot_index >= 0 && d.frames_received > 0) ? 1 : 0;
    return streaming >= snap.slots.size();
  }

  // The first of the trial's files that already exists (none with allow_overwrite).
  std::optional<std::filesystem::path> existing_file(const std::string& name) const {
    if (cfg.allow_overwrite) return std::nullopt;
    const TrialFiles paths = checked_trial_files(cfg.output_dir, name);
    for (const auto& p : {paths.recording, paths.sidecar, paths.truth_trc})
      if (std::filesystem::exists(p)) return p;
    return std::nullopt;
  }

  void refuse_existing(const std::string& name) {
    if (const auto p = existing_file(name)) {
      result.existing = *p;
      throw Error(p->string() + " exists; choose another trial name");
    }
  }

  void begin_recording() {
    RecorderConfig rc;
    rc.output_dir = cfg.output_dir;
    rc.trial = trial;
    rc.layout = cfg.sidecar_layout ? *cfg.sidecar_layout : hub.layout();
    rc.backend = cfg.backend;
    rc.extra = cfg.extra;
    rc.open_sink = cfg.open_sink;
    rc.wait_for_go = true;
    rc.trial_window = {{"countdown_s", listen() ? 0.0 : cfg.countdown_s}, {"planned_s", cfg.seconds}};
    auto rec = std::make_unique<Recorder>(rc);
    rec->start();
    recorder = std::move(rec);
    result.trial = trial;
    result.paths = recorder->paths();
    result.recorded = true;
    hub.set_consumer(recorder.get());
  }

  void send_vicon(bool start) {
    // Every device's latest frame just before CaptureStart leaves: with the send time it ties
    // each device clock to the instant Vicon starts (sidecar "vicon_alignment").
    const HubSnapshot before = hub.snapshot();
    const ViconSendResult r = start ? vicon->send_start(trial) : vicon->send_stop(trial);
    if (start) vicon_start_sent = true;
    if (start && recorder && r.datagrams_sent > 0)
      recorder->note("vicon_alignment", clock_alignment_json(before, "CaptureStart sent", r.first_datagram_host_ns,
                                                             r.message.packet_id, utc_now_iso8601()));
    SidecarViconPacket p;
    p.type = start ? "CaptureStart" : "CaptureStop";
    p.packet_id = r.message.packet_id;
    p.target = vicon->target();
    p.datagrams_sent = r.datagrams_sent;
    p.host_time_utc = utc_now_iso8601();
    p.host_ns = host_now_ns();
    p.error = r.error;
    p.warning = r.warning;
    if (recorder) recorder->note_vicon_packet(p);
    if (r.datagrams_sent > 0) ++vicon_sent;
    if (!r.warning.empty()) say(r.warning);
    if (!r.ok()) {
      say(r.error);
      fail(r.error);
    } else {
      notice("Vicon " + p.type + " sent to " + p.target + " (PacketID " + std::to_string(p.packet_id) + ", " +
             std::to_string(r.datagrams_sent) + "×)");
    }
  }

  // Every refused datagram is said, with its sender: a second Vicon system or a script on the
  // lab network trying to start a trial is something the operator must hear of.
  void report_refusals() {
    std::int64_t not_listed = 0;
    for (const ViconRefusal& r : listener->take_refusals(&not_listed)) {
      say("refused " + r.what + " from " + r.sender.text() +
          (r.datagrams > 1 ? " (" + std::to_string(r.datagrams) + " datagrams)" : std::string()) +
          ": not an allowed Vicon host (allowed: " + cfg.vicon_senders.describe() + ")");
    }
    if (not_listed > 0)
      say("refused " + std::to_string(not_listed) + " more datagram(s) from hosts that are not allowed (not listed)");
  }

  // The sidecar's vicon_listen: where, from whom, and what was refused.
  SidecarViconListen listen_record() const {
    SidecarViconListen l;
    l.address = result.listen_address;
    l.binding = listen_binding;
    l.any_sender = cfg.vicon_senders.any();
    l.allowed_senders = l.any_sender ? std::string() : cfg.vicon_senders.describe();
    l.trigger_host = trigger_sender ? trigger_sender->host() : std::string();
    l.refused_datagrams = listener->refused();
    l.refused_senders = listener->refused_by_host();
    l.warning = listen_warning;
    return l;
  }

  // Vicon's own start/stop broadcasts (listen mode), in the order they arrived.
  void handle_vicon_inbox() {
    if (!listener) return;
    report_refusals();
    // Datagrams that are not capture messages (another program on the port, a damaged packet)
    // change nothing, but the operator hears of them once per burst.
    if (const int rejected = listener->rejected(); rejected > rejected_reported) {
      say("ignored " + std::to_string(rejected - rejected_reported) + " datagram(s) on " + result.listen_address +
          " that are not Vicon capture messages (latest: " + listener->last_rejection() + ")");
      rejected_reported = rejected;
    }
    std::vector<Arrived> got;
    {
      std::lock_guard lock(inbox_mutex);
      got.swap(inbox);
    }
    for (const auto& [m, received_ns, from] : got) {
      if (m.type == ViconMessage::Type::kStart && !recorder) {
        if (cfg.trial.empty()) {
          if (auto why = validate_trial_name(m.name); !why.empty()) {
            say("ignoring CaptureStart: its Name cannot be a trial name (" + why + ")");
            continue;
          }
          // One CaptureStart naming a trial that is already on disk is refused, not the whole
          // listen session: the operator renames the trial in Nexus and starts again.
          if (const auto taken = existing_file(m.name)) {
            say("ignoring CaptureStart '" + m.name + "': " + taken->string() +
                " exists; waiting for a CaptureStart with another trial name");
            continue;
          }
          trial = m.name;
        }
        vicon_start_name = m.name;
        vicon_start_received = true;
        trigger_sender = from;
        begin_recording();
        // Vicon's start is the trial's go: no countdown of ours comes after it.
        if (sim != nullptr) sim_time_at_start = sim->simulated_time_s();
        open_window(received_ns, false);  // CaptureStop or --seconds ends it
        recorder->note("vicon_alignment", clock_alignment_json(hub.snapshot(), "CaptureStart received", received_ns,
                                                               m.packet_id, utc_now_iso8601()));
        recorder->note("vicon_trigger_received", {{"type", "CaptureStart"},
                                                  {"name", m.name},
                                                  {"packet_id", m.packet_id},
                                                  {"sender", from.text()},
                                                  {"host_time_utc", utc_now_iso8601()}});
        recorder->note_vicon_listen(listen_record());
        notice("CaptureStart received from " + from.text() + ": recording " + trial);
      } else if (m.type == ViconMessage::Type::kStop && recorder) {
        // Another capture's CaptureStop (a second Nexus, a stale broadcast) must not end this
        // trial; a Stop without a Name, or after a Start without one, is taken as ours.
        if (!m.name.empty() && !vicon_start_name.empty() && m.name != vicon_start_name) {
          say("ignoring CaptureStop for '" + m.name + "' (PacketID " + std::to_string(m.packet_id) + "): recording '" +
              vicon_start_name + "'");
          continue;
        }
        // The Vicon that started the trial stops it: with several allowed hosts (a subnet) another
        // system's CaptureStop must not end this subject's trial.
        if (trigger_sender && from.address != trigger_sender->address) {
          say("ignoring CaptureStop from " + from.text() + " (PacketID " + std::to_string(m.packet_id) +
              "): the trial was started by " + trigger_sender->host());
          continue;
        }
        recorder->note("vicon_stop_received", {{"name", m.name},
                                               {"packet_id", m.packet_id},
                                               {"result", m.result},
                                               {"sender", from.text()},
                                               {"host_time_utc", utc_now_iso8601()}});
        vicon_stop_received = true;
      }
    }
  }

  // True when the trial must end now (the reason is in `failure` / `interrupted`).
  bool must_end() {
    handle_vicon_inbox();
    if (recorder && recorder->failed()) {
      fail(recorder->status().error);
      return true;
    }
    if (!failure.empty() || vicon_stop_received) return true;
    if (stop.stop_requested()) {
      interrupted = true;
      return true;
    }
    return false;
  }

  // Listen mode: the listener that queues Vicon's CaptureStart and CaptureStop for the trial's loop.
  void start_vicon_listener() {
    const ViconListenBinding binding = choose_vicon_listen_binding(cfg.vicon_listen->first, cfg.vicon_senders);
    ViconListenerConfig lc;
    lc.bind_address = binding.address;
    lc.interface_name = binding.interface_name;
    lc.port = cfg.vicon_listen->second;
    lc.allowed = cfg.vicon_senders;
    listener = std::make_unique<ViconListener>(lc, [this](const ViconMessage& m, const ViconSender& from) {
      const std::int64_t at = host_now_ns();
      std::lock_guard lock(inbox_mutex);
      inbox.push_back({m, at, from});
    });
    const bool on_interface = !binding.interface_name.empty() && listener->interface_note().empty();
    result.listen_address = binding.address + ":" + std::to_string(listener->port()) +
                            (on_interface ? " on " + binding.interface_name : std::string());
    listen_binding = listener->interface_note().empty() ? binding.note : listener->interface_note();
    if (!listener->interface_note().empty()) say(listener->interface_note());
    if (cfg.vicon_senders.any()) {
      listen_warning =
          "no Vicon host is configured: CaptureStart and CaptureStop from any sender on the network are obeyed; "
          "name the lab's Vicon host(s) to accept only them";
      say(listen_warning);
    }
    notice("waiting for CaptureStart on " + result.listen_address + " from " + cfg.vicon_senders.describe());
  }

  // The files exist before the devices stream (a name taken or a full disk is said before the
  // subject is cued), but no row is written before go. Who opens the window: the simulator at its
  // go, at once for a replay faster than real time, or the countdown below.
  void prepare_start() {
    if (!listen()) begin_recording();
    sim_decides_go = sim != nullptr && !listen() && !hub.running();
    if (sim_decides_go) {
      sim->set_go(cfg.countdown_s, [this](std::int64_t host_ns) { open_window(host_ns, !sim_decides_length()); });
    } else if (!listen() && !hub.realtime()) {
      // A replay run faster than real time has no countdown and no clock of the subject's: its
      // trial is every row it plays.
      open_window(std::numeric_limits<std::int64_t>::min(), false);
    }
    if (!hub.running()) {
      hub.start();
      hub_started_here = true;
    }
  }

  // Each wait below returns false when the trial must end before recording.
  bool wait_for_vicon_start() {
    set_phase(TrialPhase::kWaitingForVicon, "waiting for Vicon's CaptureStart");
    while (!recorder) {
      if (must_end()) return false;
      if (hub.sources_finished()) return false;  // nothing more will stream
      tick();
    }
    return true;
  }

  bool wait_for_streams() {
    set_phase(TrialPhase::kWaitingForStreams, "waiting for every device to stream");
    const double wait_from = wall_s();
    while (!(all_streaming() || hub.sources_finished())) {
      if (must_end()) return false;
      if (wall_s() - wait_from > cfg.stream_timeout_s) {
        std::ostringstream why;
        why << "not every device of layout '" << hub.layout().name << "' streamed within " << cfg.stream_timeout_s
            << " s";
        fail(why.str());
        return false;
      }
      tick();
    }
    return true;
  }

  bool count_down_to_go() {
    if (sim_decides_go) {
      // The simulator counts down in its own time and opens the window itself at go.
      countdown_from = 0;
      if (cfg.countdown_s > 0) set_phase(TrialPhase::kCountdown, "countdown");
      while (!went.load()) {
        if (must_end()) return false;
        if (hub.sources_finished()) break;
        tick();
      }
      sim_time_at_start = sim->go_s();
    } else {
      if (cfg.countdown_s > 0) {
        countdown_from = clock_s();
        set_phase(TrialPhase::kCountdown, "countdown");
        while (clock_s() - countdown_from < cfg.countdown_s) {
          if (must_end()) return false;
          if (hub.sources_finished()) break;
          tick();
        }
      }
      if (sim != nullptr) sim_time_at_start = sim->simulated_time_s();
      open_window(host_now_ns(), true);
    }
    // Vicon records the same window: CaptureStart leaves at go, CaptureStop at the end.
    if (vicon) {
      send_vicon(true);
      if (must_end()) return false;
    }
    return true;
  }

  void record_until_end() {
    recording_from = sim_decides_go ? sim->go_s() : clock_s();
    recording_started = true;
    set_phase(TrialPhase::kRecording, "recording " + trial);
    for (;;) {
      if (must_end() || hub.sources_finished()) break;
      if (!sim_decides_length() && clock_s() - recording_from >= cfg.seconds) break;
      tick();
    }
  }

  void execute() {
    if (!(cfg.seconds > 0)) throw Error("the trial length must be > 0 s");
    if (!listen() || !trial.empty()) {
      require_valid_trial_name(trial);
      refuse_existing(trial);
    }
    if (cfg.vicon) vicon = std::make_unique<ViconTrigger>(*cfg.vicon);
    if (listen()) start_vicon_listener();
    prepare_start();
    if (listen() && !wait_for_vicon_start()) return;
    if (!wait_for_streams()) return;
    if (!listen() && !count_down_to_go()) return;
    record_until_end();
  }

  void write_truth() {
    const SimConfig& sc = sim->rig().config();
    const double from = sim_time_at_start;
    const double until = sim->finished() && sim->end_s() > 0 ? sim->end_s() : sim->simulated_time_s();
    const double seconds = until - from;
    auto truth = sim->truth_until(from + seconds);
    // TRC frame i is simulated time i / rate: the file starts at the first truth frame at or
    // after the recording's start.
    const auto skip = static_cast<size_t>(std::ceil(from * sc.truth_rate_hz - 1e-9));
    truth.erase(truth.begin(), truth.begin() + static_cast<std::ptrdiff_t>(std::min(skip, truth.size())));
    const TrcData trc = truth_trc(truth, sc.truth_rate_hz, sim->rig().marker_map());
    const double first_s = static_cast<double>(skip) / sc.truth_rate_hz;
    save_trc(result.paths.truth_trc, trc);
    SidecarGroundTruth gt;
    gt.file = result.paths.truth_trc.filename().string();
    gt.rate_hz = sc.truth_rate_hz;
    gt.frames = trc.frame_count();
    gt.device_clock_at_time_zero_us = sc.device_clock_start_us + static_cast<std::int64_t>(std::llround(first_s * 1e6));
    gt.mapping = "assets/mappings/vicon-26-to-lmc.json (exact inverse)";
    recorder->note_ground_truth(gt);
    result.truth_seconds = seconds;
  }

  // Runs `step`; an exception becomes the trial's failure (when it has none yet), never an escape.
  template <typename F>
  void guarded(const char* what, F&& step) {
    try {
      step();
    } catch (const std::exception& e) {
      fail(std::string(what) + e.what());
    } catch (...) {
      fail(std::string(what) + "unknown error");
    }
  }

  // A frame is stamped when it arrives and handed on a moment later; a frame stamped just before
  // the window's end may reach the recorder after it. The recorder stays attached until every
  // controller still streaming has handed on a frame from the end on (frames of one controller
  // come in order, so none of its window is still on its way), or the limit passes: then the
  // controllers still behind are named in the sidecar and the verdict, never dropped silently.
  void wait_for_streams_past_end() {
    if (!recorder || !went.load()) return;
    const std::int64_t until = recorder->window_until_ns();
    if (until == std::numeric_limits<std::int64_t>::max()) return;  // open until the recorder stops
    const auto deadline = Clock::now() + kStreamsPastEndLimit;
    for (;;) {
      if (hub.sources_finished()) return;  // a finished source has handed on everything
      const HubSnapshot snap = hub.snapshot();
      // Stopped early: the window ends now (on the hub's clock), not at its planned end.
      const std::int64_t end = std::min(until, snap.host_time_ns);
      std::vector<std::string> behind;
      for (const int id : recorder->devices_behind(end))
        for (const DeviceStatus& d : snap.devices)
          if (d.connected && d.slot_index + 1 == id) behind.push_back(d.slot);
      if (behind.empty()) return;
      if (Clock::now() >= deadline) {
        std::string names;
        for (const auto& b : behind) names += (names.empty() ? "" : ", ") + b;
        notice(names + ": no frame from after the trial's end within " + std::to_string(kStreamsPastEndLimit.count()) +
               " ms; its last frames may be missing");
        recorder->note_streams_behind_end(std::move(behind));
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }

  void finish() {
    recording_until = clock_s();
    guarded("", [&] { set_phase(TrialPhase::kFinishing, "finishing " + trial); });
    guarded("", [&] { wait_for_streams_past_end(); });
    // The engine's own hub stops first, so the simulator's truth covers exactly what was delivered.
    if (hub_started_here) hub.stop();
    hub.set_consumer(nullptr);
    if (listener) {
      guarded("", [&] { report_refusals(); });  // the last refusals are said too
      result.vicon_refused = listener->refused();
      result.vicon_trigger_host = trigger_sender ? trigger_sender->host() : std::string();
      if (recorder) recorder->note_vicon_listen(listen_record());
    }
    listener.reset();
    if (vicon_start_sent) guarded("cannot send CaptureStop: ", [&] { send_vicon(false); });
    if (recorder) {
      if (interrupted) recorder->note_stopped_by(cfg.stopped_by);
      if (sim != nullptr) guarded("cannot write the ground truth: ", [&] { write_truth(); });
      // An outside error makes the sidecar say "aborted" with it; a write error of the
      // recorder's own stays "failed".
      result.recorder = recorder->stop(hub.serial_to_slot(), failure);
      result.go_utc = recorder->window_from_utc();
      switch (result.recorder.state) {
        case RecorderState::kFailed:
          result.outcome = TrialOutcome::kFailed;
          result.reason = result.recorder.error;
          break;
        case RecorderState::kAborted:
          result.outcome = TrialOutcome::kAborted;
          result.reason = failure;
          break;
        default:
          result.outcome = interrupted ? TrialOutcome::kInterrupted : TrialOutcome::kCompleted;
          if (interrupted) result.reason = "stopped by " + cfg.stopped_by;
      }
    } else {
      result.outcome = interrupted && failure.empty() ? TrialOutcome::kInterrupted : TrialOutcome::kFailed;
      result.reason = failure.empty() ? "no CaptureStart received; nothing recorded" : failure;
    }
    guarded("", [&] { set_phase(TrialPhase::kDone, std::string("trial ") + trial_outcome_name(result.outcome)); });
  }
};

TrialEngine::TrialEngine(DeviceHub& hub, SimSource* sim, TrialEngineConfig config)
    : hub_(hub), sim_(sim), config_(std::move(config)) {}

TrialEngine::~TrialEngine() = default;

TrialResult TrialEngine::run(std::stop_token stop, const std::function<void(const TrialSnapshot&)>& on_status) {
  TrialInProgress trial(hub_, sim_, config_, std::move(stop), on_status);
  trial.guarded("", [&] { trial.execute(); });
  trial.finish();
  return_freed_memory();
  return std::move(trial.result);
}

}  // namespace lmc::devices
