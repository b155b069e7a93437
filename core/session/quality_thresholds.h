#pragma once
// What a protocol expects of one trial type and where its quality verdict draws the line
//. Lives apart from the protocol reader and the quality check so both include it
// without including each other. Every number comes from the protocol file; the defaults here
// are what `assets/protocols/study.json` uses when a trial type says nothing.
#include <optional>
#include <string>

namespace lmc {

// A dynamic trial's joint and the range of motion the subject is asked to reach.
struct RomExpectation {
  std::string joint;        // an angle name of core/processing/measures.h: "wrist", "index_mcp", …
  double expected_deg = 0;  // the range the cue asks for (max − min over the trial)
};

// Fail is for recording faults only (a controller missing or starved, the hand absent, Vicon
// not triggered, a write error); what the study measures (poor visibility in one pose, a short
// range of motion) is at most a warn.
struct QualityThresholds {
  double fail_min_rate_hz = 5.0;  // a controller's median rate below this: starved
  double warn_min_rate_hz = 10.0;
  double fail_max_gap_s = 1.0;  // a controller silent this long (unplugged, stalled)
  double warn_max_gap_s = 0.25;
  double fail_min_hand_fraction = 0.2;      // hand seen by no controller in most of the trial
  double warn_min_hand_fraction = 0.8;      // per controller
  double warn_max_finger_unseen = 0.3;      // a finger unseen by every controller in this share of frames
  double warn_min_rom_fraction = 0.5;       // reached less than this share of the expected range
  double fail_min_duration_fraction = 0.9;  // recorded span shorter than this share of the planned one
};

}  // namespace lmc
