#pragma once
// The quality verdict seconds after a trial: per controller frames, rate, hand
// presence, gaps and drops; how often each finger is seen by at least one controller (ray-traced
// against the block's layout, the engine processing uses); the range of motion the trial's joint
// reached; the Vicon trigger's fate. The verdict is pass, warn or fail with reasons in plain
// words. Fail is only for recording faults (a controller missing or starved, the hand absent,
// Vicon not triggered, a write error, a trial cut short): what the study measures (the initial
// layout seeing a vertical hand poorly) is at most a warn and never a reason to redo.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/lmc_recording.h"
#include "core/io/recorder_sidecar.h"
#include "core/layout/layout.h"
#include "core/session/quality_thresholds.h"

namespace lmc {

struct DeviceQuality {
  int device_id = 0;
  std::string slot;
  std::string serial;
  std::int64_t frames = 0;
  double median_rate_hz = 0;  // from consecutive device timestamps
  double rate_p5_hz = 0, rate_p95_hz = 0;
  double hand_fraction = 0;      // of its frames
  double longest_gap_s = 0;      // longest silence between frames, or at either end
  double longest_no_hand_s = 0;  // longest run of frames without a hand (hand frame to hand frame)
  std::int64_t frame_id_gaps = 0;
  std::int64_t dropped = 0;  // frames the recorder could not keep up with
  int disconnects = 0;
  // Frames whose only hand the controller classified as the other side (kept as the subject's
  // hand; the sidecar counts them). Many mean the controller is confused: mounting or tracking mode.
  std::int64_t other_side_hand_frames = 0;
};

struct RomQuality {
  std::string joint;  // as in the protocol (an angle name of core/processing/measures.h)
  double expected_deg = 0;
  double reached_deg = 0;  // 95th − 5th percentile of the fused angle over the trial (NaN if unknown)
};

struct ViconQuality {
  bool expected = false;  // the trial was meant to trigger Vicon
  bool start_sent = false;
  bool stop_sent = false;
  std::string error;                 // first sending error
  std::optional<bool> export_found;  // set when an export folder was configured
  std::string export_file;
  // Listen mode (the sidecar's vicon_listen): who started the trial, and what was refused.
  bool listened = false;
  std::string trigger_host;            // "" when no CaptureStart was obeyed
  bool any_sender = false;             // no Vicon host was configured
  std::int64_t refused_datagrams = 0;  // from hosts that are not allowed
  std::vector<std::string> refused_hosts;
};

// The trial over time, for the verdict's plot: the recorded span cut into equal slices. Kept in
// memory with the report only (quality_to_json leaves it out: the journal stays small, and the
// recording it comes from is in the session folder).
struct QualityTimeline {
  double slice_s = 0;
  std::vector<int> device_ids;  // one per series below, ascending
  std::vector<std::vector<double>>
      hand_present;  // [device][slice]: share of the slice's instants its latest row had a hand
  std::vector<std::vector<double>> fingers_seen;  // [device][slice]: mean number of fingers (0–5) it saw (ray-traced)
  // [slice]: over the slice's instants with a hand, the mean of how many controllers saw the
  // least-seen finger (0: some finger seen by nobody); NaN when no controller had the hand.
  std::vector<double> worst_finger_seen_by;
  int slices() const { return static_cast<int>(worst_finger_seen_by.size()); }
};

struct QualityReport {
  std::string verdict = "pass";      // pass | warn | fail
  std::vector<std::string> reasons;  // one line each, most serious first
  double duration_s = 0;             // recorded span on the device clocks
  double planned_s = 0;
  double hand_fraction = 0;  // share of the trial's 10 ms instants at which some controller had the hand
  std::vector<DeviceQuality> devices;
  // thumb…pinky: share of the instants with a hand at which ≥ 1 controller saw the finger
  // (ray-traced label 1); NaN when no controller ever had the hand.
  std::vector<double> finger_seen_fraction;
  std::optional<RomQuality> rom;
  ViconQuality vicon;
  QualityTimeline timeline;  // empty when the controllers' clocks jumped (no common time axis)
};

struct QualityInputs {
  const LmcRecording* recording = nullptr;   // required
  const RecorderSidecar* sidecar = nullptr;  // required
  Layout layout;                             // the block's layout; when empty, the sidecar's
  double planned_s = 0;
  QualityThresholds thresholds;
  std::vector<RomExpectation> rom;  // dynamic trials: the joint and what it should reach
  bool vicon_expected = false;
  std::optional<std::filesystem::path> vicon_export_dir;  // where <trial>.trc / .c3d should appear
};

QualityReport assess_trial(const QualityInputs& in);

nlohmann::json quality_to_json(const QualityReport& report);
// Reads what quality_to_json wrote (the journal and the manifest keep it); `source` for errors.
QualityReport quality_from_json(const nlohmann::json& j, const std::string& source);

}  // namespace lmc
