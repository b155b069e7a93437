// TrialEngine: one trial from streams to sidecar, driven by the simulator in simulated time
// (speed 0 with a duration), so lengths and truth frame counts are exact. Stops come from the
// status callback at a known phase, never from a timer.
#include "devices/record/trial_engine.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/recorder_sidecar.h"
#include "core/io/trc.h"
#include "core/session/trial_quality.h"
#include "devices/host_clock.h"
#include "devices/replay/replay_source.h"
#include "devices/sim/sim_rig.h"
#include "tests/devices/vicon/vicon_send_from.h"
#include "tests/support/reference_data.h"

namespace lmc::devices {
namespace trial_engine_test {  // named: test files share unity batches

using ::testing::ElementsAre;
using ::testing::HasSubstr;

Layout paper_initial_layout() {
  return load_layout(test::asset_file("layouts/paper-initial.json"));
}

// A hub playing a simulator of `sim_layout` (default: the hub's own) for `duration_s` simulated
// seconds (0: until stopped) at `speed` (0: simulated time, as fast as the recorder takes it).
struct SimHub {
  DeviceHub hub;
  SimSource* sim = nullptr;
  SimHub(const Layout& layout, double duration_s, double speed = 0.0, std::optional<Layout> sim_layout = {})
      : hub(layout, options(speed)) {
    SimConfig config;
    config.seed = 7;
    auto source = std::make_unique<SimSource>(sim_layout.value_or(layout), config, SimSourceOptions{speed, duration_s});
    sim = source.get();
    hub.add_source(std::move(source));
  }
  static HubOptions options(double speed) {
    HubOptions o;
    o.backpressure = speed == 0.0;  // simulated time: nothing is dropped
    return o;
  }
};

TrialEngineConfig config_for(const std::filesystem::path& dir, const std::string& trial, double seconds) {
  TrialEngineConfig c;
  c.output_dir = dir;
  c.trial = trial;
  c.seconds = seconds;
  c.backend = "sim";
  c.extra["session"] = "S01";
  return c;
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The phases a run reported, each once, in the order first seen.
std::vector<TrialPhase> distinct(const std::vector<TrialPhase>& seen) {
  std::vector<TrialPhase> out;
  for (const TrialPhase p : seen)
    if (out.empty() || out.back() != p) out.push_back(p);
  return out;
}

TEST(TrialEngine, ACompletedTrialWritesRecordingSidecarAndTruth) {
  const auto dir = test::scratch_dir("trial_engine_completed");
  SimHub sh(paper_initial_layout(), 2.0);
  TrialEngine engine(sh.hub, sh.sim, config_for(dir, "T1", 2.0));
  const TrialResult r = engine.run();

  EXPECT_EQ(r.outcome, TrialOutcome::kCompleted) << r.reason;
  EXPECT_EQ(r.reason, "");
  EXPECT_TRUE(r.recorded);
  EXPECT_EQ(r.trial, "T1");
  EXPECT_EQ(r.paths.recording, dir / "LMC_T1.raw.txt");
  EXPECT_FALSE(sh.hub.running()) << "the engine started the hub, so it stops it";

  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  EXPECT_TRUE(side.complete());
  EXPECT_EQ(side.status, "completed");
  EXPECT_EQ(side.backend, "sim");
  EXPECT_EQ(side.extra.at("session"), "S01");
  EXPECT_EQ(side.stopped_by, "");
  ASSERT_EQ(side.devices.size(), 4u);
  EXPECT_EQ(side.serial_to_slot.size(), 4u);
  EXPECT_EQ(side.frames_written, r.recorder.frames_written);
  EXPECT_EQ(side.frames_dropped, 0);
  const LmcRecording rec = read_lmc_recording(r.paths.recording);
  EXPECT_EQ(static_cast<std::int64_t>(rec.rows.size()), side.frames_written) << "every row counted is in the file";
  EXPECT_EQ(rec.device_ids(), (std::vector<int>{1, 2, 3, 4}));

  // Two simulated seconds of truth at 100 Hz, starting at simulated time 0.
  EXPECT_DOUBLE_EQ(r.truth_seconds, 2.0);
  ASSERT_TRUE(side.ground_truth.has_value());
  EXPECT_EQ(side.ground_truth->file, "T1.trc");
  EXPECT_EQ(side.ground_truth->frames, 200);
  EXPECT_EQ(side.ground_truth->device_clock_at_time_zero_us, SimConfig{}.device_clock_start_us);
  EXPECT_EQ(read_trc(r.paths.truth_trc).frame_count(), 200);
}

TEST(TrialEngine, StatusReportsThePhasesInOrder) {
  const auto dir = test::scratch_dir("trial_engine_phases");
  SimHub sh(paper_initial_layout(), 3.0);
  TrialEngineConfig c = config_for(dir, "P1", 2.0);
  c.countdown_s = 1.0;
  TrialEngine engine(sh.hub, sh.sim, c);
  std::vector<TrialPhase> seen;
  std::vector<std::string> trials;
  TrialSnapshot last;
  const TrialResult r = engine.run({}, [&](const TrialSnapshot& s) {
    seen.push_back(s.phase);
    trials.push_back(s.trial);
    last = s;
  });
  EXPECT_EQ(r.outcome, TrialOutcome::kCompleted) << r.reason;
  EXPECT_THAT(distinct(seen), ElementsAre(TrialPhase::kWaitingForStreams, TrialPhase::kCountdown,
                                          TrialPhase::kRecording, TrialPhase::kFinishing, TrialPhase::kDone));
  for (const auto& t : trials) EXPECT_EQ(t, "P1");
  EXPECT_EQ(last.phase, TrialPhase::kDone);
  EXPECT_EQ(last.message, "trial completed");
  EXPECT_EQ(last.hub.slots.size(), 4u);
  EXPECT_EQ(std::string(trial_phase_name(TrialPhase::kCountdown)), "countdown");
  EXPECT_EQ(std::string(trial_outcome_name(TrialOutcome::kInterrupted)), "interrupted");
}

TEST(TrialEngine, ASlotThatNeverStreamsAbortsTheTrialAndKeepsTheRows) {
  const auto dir = test::scratch_dir("trial_engine_timeout");
  // The hub expects four controllers; the simulator has only the first three. Real time, so the
  // three stream while the engine waits for the fourth.
  Layout three = paper_initial_layout();
  three.devices.pop_back();
  SimHub sh(paper_initial_layout(), 0.0, 1.0, three);
  TrialEngineConfig c = config_for(dir, "Silent", 5.0);
  c.stream_timeout_s = 0.3;
  TrialEngine engine(sh.hub, sh.sim, c);
  const TrialResult r = engine.run();

  EXPECT_EQ(r.outcome, TrialOutcome::kAborted);
  EXPECT_THAT(r.reason, HasSubstr("not every device of layout 'paper-initial' streamed within 0.3 s"));
  EXPECT_TRUE(r.recorded);
  EXPECT_FALSE(sh.hub.running());
  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  EXPECT_EQ(side.status, "aborted");
  EXPECT_EQ(side.error, r.reason);
  EXPECT_EQ(static_cast<std::int64_t>(read_lmc_recording(r.paths.recording).rows.size()), side.frames_written);
  for (const auto& d : side.devices) EXPECT_LE(d.device_id, 3) << "the silent slot has no rows";
}

TEST(TrialEngine, TheStopTokenInterruptsTheTrialAndKeepsItsRows) {
  const auto dir = test::scratch_dir("trial_engine_stop");
  SimHub sh(paper_initial_layout(), 30.0);
  TrialEngineConfig c = config_for(dir, "Stopped", 30.0);
  c.stopped_by = "operator (test)";
  TrialEngine engine(sh.hub, sh.sim, c);
  std::stop_source stop;
  const TrialResult r = engine.run(stop.get_token(), [&](const TrialSnapshot& s) {
    if (s.phase == TrialPhase::kRecording) stop.request_stop();
  });
  EXPECT_EQ(r.outcome, TrialOutcome::kInterrupted);
  EXPECT_EQ(r.reason, "stopped by operator (test)");
  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  EXPECT_EQ(side.status, "completed") << "an early stop keeps a valid trial";
  EXPECT_EQ(side.stopped_by, "operator (test)");
  EXPECT_EQ(static_cast<std::int64_t>(read_lmc_recording(r.paths.recording).rows.size()), side.frames_written);
  // The truth covers what the simulator delivered before the stop, not the planned 30 s.
  ASSERT_TRUE(side.ground_truth.has_value());
  EXPECT_LT(r.truth_seconds, 30.0);
  EXPECT_EQ(side.ground_truth->frames, read_trc(r.paths.truth_trc).frame_count());
}

TEST(TrialEngine, StoppedWhileWaitingForViconNothingIsRecorded) {
  const auto dir = test::scratch_dir("trial_engine_listen_stop");
  SimHub sh(paper_initial_layout(), 0.0, 1.0);
  TrialEngineConfig c = config_for(dir, "", 5.0);
  c.vicon_listen = std::make_pair(std::string("127.0.0.1"), std::uint16_t{0});
  TrialEngine engine(sh.hub, sh.sim, c);
  std::stop_source stop;
  std::vector<std::string> notices;
  const TrialResult r = engine.run(stop.get_token(), [&](const TrialSnapshot& s) {
    for (const auto& n : s.new_notices) notices.push_back(n);
    if (s.phase == TrialPhase::kWaitingForVicon) stop.request_stop();
  });
  EXPECT_EQ(r.outcome, TrialOutcome::kInterrupted);
  EXPECT_FALSE(r.recorded);
  EXPECT_EQ(r.reason, "no CaptureStart received; nothing recorded");
  EXPECT_THAT(r.listen_address, HasSubstr("127.0.0.1:"));
  ASSERT_FALSE(notices.empty());
  EXPECT_EQ(notices.front(), "waiting for CaptureStart on " + r.listen_address + " from any sender");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// Vicon listen mode: a CaptureStart naming a trial already on disk is refused on its
// own (the session keeps listening), and another capture's CaptureStop does not end this trial.
TEST(TrialEngine, ListenModeSkipsATakenNameAndIgnoresAnotherTrialsStop) {
  const auto dir = test::scratch_dir("trial_engine_listen_names");
  std::ofstream(dir / "Taken.trc") << "keep me\n";
  SimHub sh(paper_initial_layout(), 0.0, 1.0);
  TrialEngineConfig c = config_for(dir, "", 30.0);
  c.vicon_listen = std::make_pair(std::string("127.0.0.1"), std::uint16_t{0});
  TrialEngine engine(sh.hub, sh.sim, c);
  std::stop_source stop;
  std::unique_ptr<ViconTrigger> vicon;
  std::vector<std::string> messages;
  int step = 0;
  const auto seen = [&](const std::string& fragment) {
    return std::any_of(messages.begin(), messages.end(),
                       [&](const std::string& m) { return m.find(fragment) != std::string::npos; });
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(40);  // a hang guard only
  const std::string waiting = "waiting for CaptureStart on 127.0.0.1:";
  const TrialResult r = engine.run(stop.get_token(), [&](const TrialSnapshot& s) {
    for (const auto& m : s.new_messages) messages.push_back(m);
    for (const auto& n : s.new_notices) {
      if (vicon || n.rfind(waiting, 0) != 0) continue;
      ViconTriggerConfig vc;
      vc.host = "127.0.0.1";
      vc.port = static_cast<std::uint16_t>(std::stoi(n.substr(waiting.size())));
      vc.first_packet_id = 700;  // nothing persisted
      vicon = std::make_unique<ViconTrigger>(vc);
      EXPECT_TRUE(vicon->send_start("Taken").ok());
      EXPECT_TRUE(vicon->send_start("Fresh").ok());
      step = 1;
    }
    if (step == 1 && s.phase == TrialPhase::kRecording && s.recording_s > 0.2) {
      EXPECT_TRUE(vicon->send_stop("Other").ok());
      step = 2;
    }
    if (step == 2 && seen("ignoring CaptureStop for 'Other'")) {
      EXPECT_TRUE(vicon->send_stop("Fresh").ok());
      step = 3;
    }
    if (std::chrono::steady_clock::now() > deadline) stop.request_stop();
  });
  EXPECT_EQ(r.outcome, TrialOutcome::kCompleted) << r.reason;
  EXPECT_EQ(r.trial, "Fresh");
  EXPECT_EQ(step, 3);
  EXPECT_TRUE(seen("ignoring CaptureStart 'Taken': " + (dir / "Taken.trc").string() + " exists"))
      << ::testing::PrintToString(messages);
  EXPECT_TRUE(seen("ignoring CaptureStop for 'Other'")) << ::testing::PrintToString(messages);
  EXPECT_EQ(read_text(dir / "Taken.trc"), "keep me\n");
  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  EXPECT_EQ(side.status, "completed");
  EXPECT_EQ(side.vicon_stop_received.at("name"), "Fresh");
  EXPECT_EQ(side.vicon_trigger_received.at("name"), "Fresh");
}

// Only the configured Vicon host starts and stops the trial: another host's CaptureStart (even
// with the PacketID the real one then uses) and its CaptureStop for the same trial are refused,
// said with the sender, counted in the sidecar, and the verdict names both hosts.
TEST(TrialEngine, ListenModeObeysOnlyTheConfiguredViconHost) {
  const auto dir = test::scratch_dir("trial_engine_listen_hosts");
  SimHub sh(paper_initial_layout(), 0.0, 1.0);
  TrialEngineConfig c = config_for(dir, "", 30.0);
  c.vicon_listen = std::make_pair(std::string(), std::uint16_t{0});  // the interface that reaches the host
  c.vicon_senders = ViconSenders::parse("127.0.0.1");
  TrialEngine engine(sh.hub, sh.sim, c);
  std::stop_source stop;
  std::unique_ptr<ViconTrigger> vicon;
  std::uint16_t port = 0;
  std::vector<std::string> messages;
  int step = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(40);  // a hang guard only
  const TrialResult r = engine.run(stop.get_token(), [&](const TrialSnapshot& s) {
    for (const auto& m : s.new_messages) messages.push_back(m);
    if (step == 0 && s.phase == TrialPhase::kWaitingForVicon && !s.vicon_listen_address.empty()) {
      port = static_cast<std::uint16_t>(std::stoi(s.vicon_listen_address.substr(s.vicon_listen_address.find(':') + 1)));
      ViconMessage intruder;
      intruder.name = "Intruder";
      intruder.packet_id = 900;
      test::vicon_send_from("127.0.0.2", port, intruder, 3);
      ViconTriggerConfig vc;
      vc.host = "127.0.0.1";
      vc.port = port;
      vc.first_packet_id = 900;  // nothing persisted
      vicon = std::make_unique<ViconTrigger>(vc);
      EXPECT_TRUE(vicon->send_start("Fresh").ok());
      step = 1;
    }
    if (step == 1 && s.phase == TrialPhase::kRecording && s.recording_s > 0.2) {
      ViconMessage foreign_stop;
      foreign_stop.type = ViconMessage::Type::kStop;
      foreign_stop.name = "Fresh";
      foreign_stop.packet_id = 950;
      test::vicon_send_from("127.0.0.2", port, foreign_stop, 3);
      step = 2;
    }
    if (step == 2 && s.vicon_refused >= 6) {
      EXPECT_EQ(s.vicon_trigger_host, "127.0.0.1");
      EXPECT_TRUE(vicon->send_stop("Fresh").ok());
      step = 3;
    }
    if (std::chrono::steady_clock::now() > deadline) stop.request_stop();
  });
  EXPECT_EQ(r.outcome, TrialOutcome::kCompleted) << r.reason;
  EXPECT_EQ(step, 3);
  EXPECT_EQ(r.trial, "Fresh");
  EXPECT_EQ(r.vicon_trigger_host, "127.0.0.1");
  EXPECT_EQ(r.vicon_refused, 6);
  // Tied to the loopback interface (" on lo"), or, where the kernel refuses that, every interface.
  EXPECT_THAT(r.listen_address, ::testing::StartsWith("0.0.0.0:" + std::to_string(port)));
  const std::string allowed = ": not an allowed Vicon host (allowed: 127.0.0.1)";
  EXPECT_THAT(messages, ::testing::Contains(::testing::AllOf(
                            HasSubstr("refused CaptureStart 'Intruder' (PacketID 900) from 127.0.0.2:"),
                            HasSubstr("(3 datagrams)" + allowed))));
  EXPECT_THAT(messages,
              ::testing::Contains(::testing::AllOf(
                  HasSubstr("refused CaptureStop 'Fresh' (PacketID 950) from 127.0.0.2:"), HasSubstr(allowed))));
  EXPECT_THAT(messages, ::testing::Not(::testing::Contains(HasSubstr("any sender"))));

  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  EXPECT_EQ(side.status, "completed");
  EXPECT_THAT(side.vicon_trigger_received.at("sender").get<std::string>(), ::testing::StartsWith("127.0.0.1:"));
  EXPECT_EQ(side.vicon_stop_received.at("packet_id"), 901);
  ASSERT_TRUE(side.vicon_listen.has_value());
  EXPECT_EQ(side.vicon_listen->trigger_host, "127.0.0.1");
  EXPECT_EQ(side.vicon_listen->allowed_senders, "127.0.0.1");
  EXPECT_FALSE(side.vicon_listen->any_sender);
  EXPECT_EQ(side.vicon_listen->refused_datagrams, 6);
  EXPECT_THAT(side.vicon_listen->refused_senders,
              ElementsAre(std::make_pair(std::string("127.0.0.2"), std::int64_t{6})));
  EXPECT_THAT(side.vicon_listen->binding, HasSubstr("127.0.0.1"));
  EXPECT_TRUE(side.vicon_listen->warning.empty());

  const LmcRecording rec = read_lmc_recording(r.paths.recording);
  QualityInputs in;
  in.recording = &rec;
  in.sidecar = &side;
  const QualityReport q = assess_trial(in);
  EXPECT_TRUE(q.vicon.listened);
  EXPECT_EQ(q.vicon.trigger_host, "127.0.0.1");
  EXPECT_EQ(q.vicon.refused_datagrams, 6);
  EXPECT_THAT(q.reasons,
              ::testing::Contains("6 Vicon datagram(s) from hosts that may not trigger were refused (127.0.0.2)"));
  const QualityReport back = quality_from_json(quality_to_json(q), "verdict");
  EXPECT_EQ(back.vicon.trigger_host, "127.0.0.1");
  EXPECT_EQ(back.vicon.refused_datagrams, 6);
  EXPECT_THAT(back.vicon.refused_hosts, ElementsAre("127.0.0.2"));
}

// No host configured: it still works, and says loudly (messages, sidecar, verdict) that anyone
// could have triggered it.
TEST(TrialEngine, ListenModeWithoutAViconHostWarnsThatAnySenderIsObeyed) {
  const auto dir = test::scratch_dir("trial_engine_listen_any");
  SimHub sh(paper_initial_layout(), 0.0, 1.0);
  TrialEngineConfig c = config_for(dir, "", 30.0);
  c.vicon_listen = std::make_pair(std::string("127.0.0.1"), std::uint16_t{0});
  TrialEngine engine(sh.hub, sh.sim, c);
  std::stop_source stop;
  std::vector<std::string> messages;
  bool sent = false, stopped = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(40);  // a hang guard only
  const TrialResult r = engine.run(stop.get_token(), [&](const TrialSnapshot& s) {
    for (const auto& m : s.new_messages) messages.push_back(m);
    const auto port = [&] {
      return static_cast<std::uint16_t>(std::stoi(s.vicon_listen_address.substr(s.vicon_listen_address.find(':') + 1)));
    };
    if (!sent && s.phase == TrialPhase::kWaitingForVicon && !s.vicon_listen_address.empty()) {
      ViconMessage start;
      start.name = "Anyone";
      start.packet_id = 40;
      test::vicon_send_from("127.0.0.2", port(), start, 3);
      sent = true;
    }
    if (sent && !stopped && s.phase == TrialPhase::kRecording && s.recording_s > 0.2) {
      ViconMessage end;
      end.type = ViconMessage::Type::kStop;
      end.name = "Anyone";
      end.packet_id = 41;
      test::vicon_send_from("127.0.0.2", port(), end, 3);
      stopped = true;
    }
    if (std::chrono::steady_clock::now() > deadline) stop.request_stop();
  });
  EXPECT_EQ(r.outcome, TrialOutcome::kCompleted) << r.reason;
  EXPECT_EQ(r.vicon_trigger_host, "127.0.0.2");
  EXPECT_EQ(r.vicon_refused, 0);
  EXPECT_THAT(messages, ::testing::Contains(
                            HasSubstr("no Vicon host is configured: CaptureStart and CaptureStop from any sender")));
  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  ASSERT_TRUE(side.vicon_listen.has_value());
  EXPECT_TRUE(side.vicon_listen->any_sender);
  EXPECT_EQ(side.vicon_listen->trigger_host, "127.0.0.2");
  EXPECT_THAT(side.vicon_listen->warning, HasSubstr("any sender"));
  const LmcRecording rec = read_lmc_recording(r.paths.recording);
  QualityInputs in;
  in.recording = &rec;
  in.sidecar = &side;
  EXPECT_THAT(
      assess_trial(in).reasons,
      ::testing::Contains(
          "Vicon listen mode obeyed any sender (CaptureStart came from 127.0.0.2): no Vicon host was configured"));
}

TEST(TrialEngine, RefusesToOverwriteAnExistingTrial) {
  const auto dir = test::scratch_dir("trial_engine_refuse");
  // Any one of the trial's three files makes the name taken, a Vicon export too.
  for (const std::string file : {"LMC_Taken.raw.txt", "LMC_Taken.session.json", "Taken.trc"}) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ofstream(dir / file) << "keep me\n";
    SimHub sh(paper_initial_layout(), 1.0);
    TrialEngine engine(sh.hub, sh.sim, config_for(dir, "Taken", 1.0));
    const TrialResult r = engine.run();
    EXPECT_EQ(r.outcome, TrialOutcome::kFailed) << file;
    EXPECT_FALSE(r.recorded);
    EXPECT_EQ(r.existing, dir / file);
    EXPECT_THAT(r.reason, HasSubstr("exists"));
    EXPECT_EQ(read_text(dir / file), "keep me\n");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator{}), 1)
        << "nothing else was created for " << file;
    EXPECT_FALSE(sh.hub.running());
  }
  // lmc record --force: the same name is recorded over.
  SimHub sh(paper_initial_layout(), 1.0);
  TrialEngineConfig c = config_for(dir, "Taken", 1.0);
  c.allow_overwrite = true;
  const TrialResult r = TrialEngine(sh.hub, sh.sim, c).run();
  EXPECT_EQ(r.outcome, TrialOutcome::kCompleted) << r.reason;
  EXPECT_NE(read_text(dir / "Taken.trc"), "keep me\n");
}

TEST(TrialEngine, AThrowingCallbackAbortsTheTrialWithItsReasonAndKeepsTheRows) {
  const auto dir = test::scratch_dir("trial_engine_throw");
  SimHub sh(paper_initial_layout(), 2.0);
  TrialEngine engine(sh.hub, sh.sim, config_for(dir, "Thrown", 2.0));
  const TrialResult r = engine.run({}, [](const TrialSnapshot& s) {
    if (s.phase == TrialPhase::kRecording) throw std::runtime_error("display gone");
  });
  EXPECT_EQ(r.outcome, TrialOutcome::kAborted);
  EXPECT_EQ(r.reason, "display gone");
  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  EXPECT_EQ(side.status, "aborted");
  EXPECT_EQ(side.error, "display gone");
  EXPECT_EQ(static_cast<std::int64_t>(read_lmc_recording(r.paths.recording).rows.size()), side.frames_written);
}

TEST(TrialEngine, AHubThatWasRunningKeepsRunning) {
  const auto dir = test::scratch_dir("trial_engine_shared_hub");
  // The workbench's hub: real time, forever, already started; the engine times the trial in
  // simulated seconds and stops it on the token at the recording phase.
  SimHub sh(paper_initial_layout(), 0.0, 1.0);
  sh.hub.start();
  TrialEngine engine(sh.hub, sh.sim, config_for(dir, "Shared", 60.0));
  std::stop_source stop;
  const TrialResult r = engine.run(stop.get_token(), [&](const TrialSnapshot& s) {
    if (s.phase == TrialPhase::kRecording) stop.request_stop();
  });
  EXPECT_EQ(r.outcome, TrialOutcome::kInterrupted) << r.reason;
  EXPECT_TRUE(sh.hub.running());
  sh.hub.stop();
}

// One controller at 100 Hz whose frames reach the hub `delay` after they were stamped (a device
// thread held by a busy machine between stamping a frame and handing it on), going silent but
// staying connected from `silent_after` (from its start) when that is given.
class LateSource final : public FrameSource {
 public:
  LateSource(std::chrono::milliseconds delay, std::optional<std::chrono::milliseconds> silent_after = {})
      : delay_(delay), silent_after_(silent_after) {}
  ~LateSource() override { stop(); }
  std::string backend_name() const override { return "late"; }
  void start(FrameSink& sink) override {
    thread_ = std::jthread([this, &sink](std::stop_token st) { run(sink, st); });
  }
  void stop() override {
    if (thread_.joinable()) {
      thread_.request_stop();
      thread_.join();
    }
  }

 private:
  void run(FrameSink& sink, const std::stop_token& st) {
    DeviceEvent appeared;
    appeared.kind = DeviceEventKind::kAppeared;
    appeared.info = {"LATE1", "late", "test", ""};
    appeared.host_time_ns = host_now_ns();
    sink.on_device_event(appeared);
    const std::int64_t t0 = host_now_ns();
    constexpr std::int64_t kPeriodNs = 10'000'000;
    for (std::int64_t k = 0; !st.stop_requested(); ++k) {
      const std::int64_t stamp = t0 + k * kPeriodNs;
      while (host_now_ns() < stamp + delay_.count() * 1'000'000 && !st.stop_requested())
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      if (silent_after_ && stamp - t0 >= silent_after_->count() * 1'000'000) continue;
      SourceFrame f;
      f.serial = "LATE1";
      f.frame.device_id = 1;
      f.frame.frame_id = k;
      f.frame.timestamp_us = stamp / 1000;
      f.host_receive_ns = stamp;
      sink.on_frame(f);
    }
  }
  std::chrono::milliseconds delay_;
  std::optional<std::chrono::milliseconds> silent_after_;
  std::jthread thread_;
};

Layout one_late_controller() {
  Layout l;
  l.name = "late";
  LayoutDevice d;
  d.slot = "LMC1";
  d.serial = "LATE1";
  l.devices.push_back(d);
  return l;
}

TEST(TrialEngine, FramesStampedBeforeTheEndButHandedOnAfterItAreWritten) {
  const auto dir = test::scratch_dir("trial_engine_late_frames");
  DeviceHub hub(one_late_controller());
  hub.add_source(std::make_unique<LateSource>(std::chrono::milliseconds(300)));
  TrialEngineConfig c = config_for(dir, "Late1", 1.0);
  c.countdown_s = 0;
  TrialEngine engine(hub, nullptr, c);
  const TrialResult r = engine.run();
  ASSERT_EQ(r.outcome, TrialOutcome::kCompleted) << r.reason;
  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  // Every frame stamped inside the second is in the file, the last 300 ms of them included.
  const auto rows = read_lmc_recording(r.paths.recording).rows.size();
  EXPECT_GE(rows, 99u);
  EXPECT_LE(rows, 101u);
  EXPECT_FALSE(side.trial_window.contains("streams_behind_end"));
  EXPECT_GE(side.trial_window.at("frames_after_end").get<std::int64_t>(), 1) << "the wait ended on a later frame";
}

TEST(TrialEngine, AControllerSilentAtTheEndIsNamedInTheSidecarAndTheVerdict) {
  const auto dir = test::scratch_dir("trial_engine_silent_end");
  DeviceHub hub(one_late_controller());
  hub.add_source(std::make_unique<LateSource>(std::chrono::milliseconds(0), std::chrono::milliseconds(500)));
  TrialEngineConfig c = config_for(dir, "Quiet1", 1.0);
  c.countdown_s = 0;
  TrialEngine engine(hub, nullptr, c);
  const TrialResult r = engine.run();
  ASSERT_TRUE(r.recorded) << r.reason;
  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  ASSERT_TRUE(side.trial_window.contains("streams_behind_end"));
  EXPECT_EQ(side.trial_window.at("streams_behind_end"), nlohmann::json::array({"LMC1"}));
  EXPECT_THAT(r.messages, ::testing::Contains(HasSubstr("LMC1: no frame from after the trial's end within 1000 ms")));
  const LmcRecording rec = read_lmc_recording(r.paths.recording);
  const QualityReport q = assess_trial([&] {
    QualityInputs in;
    in.recording = &rec;
    in.sidecar = &side;
    in.layout = one_late_controller();
    in.planned_s = 1.0;
    return in;
  }());
  EXPECT_THAT(q.reasons, ::testing::Contains(HasSubstr("LMC1: no frame from after the trial's end reached the "
                                                       "recorder before it closed")));
}

// What the file holds of one device: the span of its rows on the device clock, and the earliest row.
struct DeviceSpan {
  std::int64_t first_us = 0, last_us = 0;
  int rows = 0;
};
std::map<int, DeviceSpan> spans(const LmcRecording& rec) {
  std::map<int, DeviceSpan> out;
  for (const auto& row : rec.rows) {
    DeviceSpan& s = out[row.device_id];
    if (s.rows == 0 || row.timestamp_us < s.first_us) s.first_us = row.timestamp_us;
    if (s.rows == 0 || row.timestamp_us > s.last_us) s.last_us = row.timestamp_us;
    ++s.rows;
  }
  return out;
}

// The simulator's slowest frame interval (11 Hz): "one frame" in the tolerances below.
constexpr std::int64_t kOneFrameUs = 1'000'000 / 11 + 1;

TEST(TrialExactness, ASimulatedTrialRecordsThePlannedSecondsFromGoAndNotTheCountdown) {
  const auto dir = test::scratch_dir("trial_exact_sim");
  // Simulated time: the countdown (1.5 s) runs in the simulator's clock, so it is exact however
  // fast the simulator plays.
  SimHub sh(paper_initial_layout(), 2.0);
  TrialEngineConfig c = config_for(dir, "Go1", 2.0);
  c.countdown_s = 1.5;
  TrialEngine engine(sh.hub, sh.sim, c);
  std::vector<TrialPhase> seen;
  const TrialResult r = engine.run({}, [&](const TrialSnapshot& s) { seen.push_back(s.phase); });
  ASSERT_EQ(r.outcome, TrialOutcome::kCompleted) << r.reason;
  EXPECT_THAT(distinct(seen), ElementsAre(TrialPhase::kWaitingForStreams, TrialPhase::kCountdown,
                                          TrialPhase::kRecording, TrialPhase::kFinishing, TrialPhase::kDone));
  const std::int64_t go_us = SimConfig{}.device_clock_start_us + 1'500'000;
  const LmcRecording rec = read_lmc_recording(r.paths.recording);
  const auto by_device = spans(rec);
  ASSERT_EQ(by_device.size(), 4u);
  for (const auto& [id, span] : by_device) {
    EXPECT_GE(span.first_us, go_us) << "LMC" << id << ": no row of the countdown is in the file";
    EXPECT_LT(span.first_us, go_us + kOneFrameUs) << "LMC" << id << ": the file starts at go";
    EXPECT_LT(span.last_us, go_us + 2'000'000) << "LMC" << id;
    EXPECT_GE(span.last_us, go_us + 2'000'000 - kOneFrameUs) << "LMC" << id << ": the trial lasts its 2 s";
  }
  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  ASSERT_TRUE(side.trial_window.is_object());
  EXPECT_DOUBLE_EQ(side.trial_window.at("countdown_s").get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(side.trial_window.at("planned_s").get<double>(), 2.0);
  EXPECT_GT(side.trial_window.at("frames_before_go").get<std::int64_t>(), 4 * 11) << "the countdown streamed";
  EXPECT_EQ(side.trial_window.at("go_host_utc").get<std::string>(), r.go_utc);
  EXPECT_EQ(side.frames_dropped, 0) << "frames of the countdown are not losses";
  // The truth covers the same window: 2 s at 100 Hz from go.
  ASSERT_TRUE(side.ground_truth.has_value());
  EXPECT_EQ(side.ground_truth->frames, 200);
  EXPECT_EQ(side.ground_truth->device_clock_at_time_zero_us, go_us);
  EXPECT_DOUBLE_EQ(r.truth_seconds, 2.0);
}

TEST(TrialExactness, TheSimulatedHandHoldsItsStartPoseUntilGoThenMovesFromItsStart) {
  SimConfig config;
  apply_motion_spec(config, "horizontal/index");
  config.sway_mm = 0;
  const Layout layout = paper_initial_layout();
  SimRig plain(layout, config);
  SimRig held(layout, config);
  held.hold_start_pose(1.5);
  const auto same = [](const HandFrame& a, const HandFrame& b) {
    for (int p = 0; p < kNumHandPoints; ++p)
      if ((a.point(p) - b.point(p)).norm() > 1e-9) return false;
    return true;
  };
  EXPECT_TRUE(same(held.truth_at(1.0), plain.truth_at(0.0))) << "still during the countdown";
  EXPECT_TRUE(same(held.truth_at(1.5), plain.truth_at(0.0))) << "the motion starts at go";
  EXPECT_TRUE(same(held.truth_at(1.5 + 0.75), plain.truth_at(0.75)));
  EXPECT_FALSE(same(plain.truth_at(0.75), plain.truth_at(0.0))) << "the index finger does move";
}

TEST(TrialExactness, AWallClockTrialIsBoundedOnTheHostClockFromGo) {
  const auto dir = test::scratch_dir("trial_exact_wall");
  // Controllers the engine does not time (LeapC, a replay, the workbench's own simulator): real
  // time, no simulator handed to the engine, so go and the end are host-clock instants.
  SimHub sh(paper_initial_layout(), 0.0, 1.0);
  TrialEngineConfig c = config_for(dir, "Wall1", 1.0);
  c.countdown_s = 0.5;
  TrialEngine engine(sh.hub, nullptr, c);
  double last_recording_s = 0;
  std::vector<TrialPhase> seen;
  const TrialResult r = engine.run({}, [&](const TrialSnapshot& s) {
    seen.push_back(s.phase);
    if (s.phase == TrialPhase::kRecording) last_recording_s = s.recording_s;
  });
  ASSERT_EQ(r.outcome, TrialOutcome::kCompleted) << r.reason;
  EXPECT_THAT(distinct(seen), ElementsAre(TrialPhase::kWaitingForStreams, TrialPhase::kCountdown,
                                          TrialPhase::kRecording, TrialPhase::kFinishing, TrialPhase::kDone));
  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  const auto go_ns = side.trial_window.at("go_host_ns").get<std::int64_t>();
  const auto end_ns = side.trial_window.at("end_host_ns").get<std::int64_t>();
  EXPECT_EQ(end_ns - go_ns, 1'000'000'000) << "the window is the planned second";
  EXPECT_GT(side.trial_window.at("frames_before_go").get<std::int64_t>(), 0) << "the countdown streamed";
  EXPECT_GE(go_ns - side.host_start_ns, 450'000'000) << "go comes after the 0.5 s countdown";
  // The window is exact on the host clock (above). What the devices delivered inside it spans the
  // second less its edge frames; on a loaded machine a starved device thread delivers late, so
  // the lower bound keeps a margin (the upper bound is the window's and holds regardless).
  for (const auto& [id, span] : spans(read_lmc_recording(r.paths.recording))) {
    const std::int64_t recorded_us = span.last_us - span.first_us;
    EXPECT_LE(recorded_us, 1'000'000) << "LMC" << id;
    EXPECT_GE(recorded_us, 750'000) << "LMC" << id << ": the second, less its edge frames";
  }
  EXPECT_GE(last_recording_s, 0.8) << "the status counted the trial from go";
}

TEST(TrialExactness, AReplayAtItsRecordedPaceIsBoundedOnTheHostClockToo) {
  const auto dir = test::scratch_dir("trial_exact_replay");
  // A 3 s simulated trial to replay (as a lab replays a recording to test its set-up).
  {
    SimHub sh(paper_initial_layout(), 3.0);
    ASSERT_EQ(TrialEngine(sh.hub, sh.sim, config_for(dir, "Source", 3.0)).run().outcome, TrialOutcome::kCompleted);
  }
  DeviceHub hub(paper_initial_layout());
  hub.add_source(std::make_unique<ReplaySource>(dir / "LMC_Source.raw.txt", ReplayOptions{1.0, false}));
  TrialEngineConfig c = config_for(dir, "Replay1", 1.0);
  c.backend = "replay";
  c.countdown_s = 0.5;
  const TrialResult r = TrialEngine(hub, nullptr, c).run();
  ASSERT_EQ(r.outcome, TrialOutcome::kCompleted) << r.reason;
  const RecorderSidecar side = read_recorder_sidecar(r.paths.sidecar);
  EXPECT_EQ(
      side.trial_window.at("end_host_ns").get<std::int64_t>() - side.trial_window.at("go_host_ns").get<std::int64_t>(),
      1'000'000'000);
  EXPECT_GT(side.trial_window.at("frames_before_go").get<std::int64_t>(), 0);
  for (const auto& [id, span] : spans(read_lmc_recording(r.paths.recording))) {
    EXPECT_LE(span.last_us - span.first_us, 1'000'000) << "LMC" << id;
    EXPECT_GE(span.last_us - span.first_us, 750'000) << "LMC" << id;  // margin as above
  }
}

}  // namespace trial_engine_test
}  // namespace lmc::devices
