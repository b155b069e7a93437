#pragma once
// One trial, start to finish: create the trial's files → wait for Vicon's CaptureStart (listen
// mode) → wait until every layout slot streams → countdown → go: the recorder's window opens and
// CaptureStart leaves (with the clock alignment note) → record for `seconds` or until stopped →
// send CaptureStop → write the simulator's ground truth → finalise the sidecar. `lmc record`, the
// session runner and the workbench drive the same class; none of them repeats the sequence.
//
// The trial is the window from go to stop, and the file holds only that window: the countdown is
// not recorded (the sidecar's trial_window says when go was and how many frames came before it),
// so processing, Review, the verdict and exports need no trimming. In listen mode Vicon's
// CaptureStart is go.
//
// Time: when the engine starts a simulator's hub (`sim` given, hub not running), the simulator
// holds the hand still for the countdown and opens the window itself at go, in simulated time,
// so `--fast` trials are exact and reproducible; a simulator with a duration ends the trial when
// it finishes. Otherwise the countdown and the trial are wall-clock seconds and the window is
// bounded on the host clock. The stream timeout is always wall-clock (it is about hardware that
// never answers).
//
// Guarantees: never overwrites a trial's files (unless allow_overwrite); every row written is
// kept whatever ends the trial; any error, also one thrown by a callback, ends as an outcome with
// a reason instead of an exception; no printing (messages come back in snapshots and the
// result). The engine starts the hub when it is not running and then stops it at the end; a hub
// that was already running (the workbench's) keeps running. It installs its recorder as the
// hub's consumer for the trial and removes it (sets none) at the end.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "devices/device_hub.h"
#include "devices/record/byte_sink.h"
#include "devices/record/recorder.h"
#include "devices/sim/sim_source.h"
#include "devices/vicon/vicon_trigger.h"

namespace lmc::devices {

// kAborted: ended by an outside error (stream timeout, Vicon refused, truth not writable, a
// throwing callback); kFailed: nothing could be recorded (name taken, bad config, socket) or the
// recorder could not write; kInterrupted: stopped early by the stop token (the operator).
enum class TrialOutcome { kCompleted, kAborted, kFailed, kInterrupted };
const char* trial_outcome_name(TrialOutcome o);  // "completed" | "aborted" | "failed" | "interrupted"

enum class TrialPhase { kWaitingForStreams, kWaitingForVicon, kCountdown, kRecording, kFinishing, kDone };
const char* trial_phase_name(TrialPhase p);  // "waiting_for_streams", "waiting_for_vicon", "countdown", …

struct TrialSnapshot {
  TrialPhase phase = TrialPhase::kWaitingForStreams;
  std::string trial;                 // empty while listen mode waits for Vicon's Name
  double elapsed_s = 0;              // wall-clock seconds since run() began
  double countdown_remaining_s = 0;  // kCountdown
  double recording_s = 0;            // trial seconds recorded (simulated with a simulator)
  double remaining_s = 0;            // of the trial (the simulator's duration when it ends the trial)
  HubSnapshot hub;
  RecorderStatus recorder;  // idle before the recorder starts
  int vicon_packets_sent = 0;
  // Vicon: whether CaptureStart/Stop are sent, or awaited (listen mode), and what came so far.
  bool vicon_sending = false;
  bool vicon_listening = false;
  std::string vicon_listen_address;  // listen mode: where CaptureStart is awaited
  std::string vicon_trigger_host;    // listen mode: who sent the CaptureStart that began the trial
  std::int64_t vicon_refused = 0;    // listen mode: datagrams refused from senders not allowed
  bool vicon_start_received = false;
  bool vicon_stop_received = false;
  std::string message;  // what is happening now, for a status line
  // Since the previous snapshot: device messages and warnings/errors (always worth showing) and
  // routine progress notes (Vicon trigger sent, CaptureStart received, …).
  std::vector<std::string> new_messages;
  std::vector<std::string> new_notices;
};

struct TrialEngineConfig {
  std::filesystem::path output_dir;
  std::string trial;  // listen mode: empty = Vicon's CaptureStart Name
  double seconds = 5;
  double countdown_s = 0;
  double stream_timeout_s = 10;
  std::string backend;                      // written to the sidecar: sim | leapc | replay
  std::optional<ViconTriggerConfig> vicon;  // send CaptureStart/Stop
  // Wait for Vicon's CaptureStart instead (address, port). An empty address: the interface that
  // reaches vicon_senders (devices/vicon/vicon_route.h), or every interface when none are given.
  std::optional<std::pair<std::string, std::uint16_t>> vicon_listen;
  // Listen mode: whose CaptureStart / CaptureStop are obeyed. Empty: any sender's, with a warning
  // in the messages, the sidecar and the verdict (vicon_senders.h says why a lab names its Vicon).
  ViconSenders vicon_senders;
  bool allow_overwrite = false;                     // lmc record --force only
  nlohmann::json extra = nlohmann::json::object();  // into the sidecar's extra (simulator config, session info…)
  // The layout the sidecar records (what processing realigns with) when it is not the hub's: a
  // session block's calibrated layout, while the hub keeps the one the controllers were set up by.
  std::optional<Layout> sidecar_layout;
  std::function<std::unique_ptr<ByteSink>(const std::filesystem::path&)> open_sink;  // tests
  std::string stopped_by = "operator";  // sidecar "stopped_by" when the stop token ends the trial
};

// What one recording attempt gave: how it ended, where its files are, what the recorder saw. What
// processing makes of those files later is a TrialAnalysis (core/processing/trial_pipeline.h).
struct TrialResult {
  TrialOutcome outcome = TrialOutcome::kFailed;
  std::string reason;  // empty when completed
  std::string trial;
  TrialFiles paths;  // empty when no trial name was known
  RecorderStatus recorder;
  double truth_seconds = 0;           // span of the simulator's ground truth file (0: none written)
  std::vector<std::string> messages;  // every message and notice, in order
  bool recorded = false;              // the recorder started: the files exist and hold the rows
  std::filesystem::path existing;     // set when refused because this file of the trial exists
  std::string listen_address;         // listen mode: where CaptureStart was awaited (port resolved)
  std::string vicon_trigger_host;     // listen mode: the sender of the CaptureStart obeyed ("" if none)
  std::int64_t vicon_refused = 0;     // listen mode: datagrams refused from senders not allowed
  std::string go_utc;                 // when the subject was told to go (the file's first row); "" if never
};

class TrialEngine {
 public:
  // `hub` and `sim` (null unless the hub plays this simulator) must outlive run(). A simulator
  // whose hub is not running yet is given the countdown (SimSource::set_go) by run().
  TrialEngine(DeviceHub& hub, SimSource* sim, TrialEngineConfig config);
  ~TrialEngine();
  TrialEngine(const TrialEngine&) = delete;
  TrialEngine& operator=(const TrialEngine&) = delete;

  // Runs the trial on the calling thread; on_status is called from it on every phase change,
  // every new message and otherwise about ten times a second.
  TrialResult run(std::stop_token stop = {}, const std::function<void(const TrialSnapshot&)>& on_status = {});

 private:
  struct TrialInProgress;
  DeviceHub& hub_;
  SimSource* sim_;
  TrialEngineConfig config_;
};

}  // namespace lmc::devices
