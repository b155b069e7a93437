#pragma once
// A recording protocol as data: which layouts, palm poses and motions a subject
// performs, how often, for how long, with which cues, and what a good trial of each kind looks
// like. `assets/protocols/study.json` is the study's 2 × 2 × 4 × 5 = 80 trials; `quick.json` a
// short one for demos and tests. A protocol file is validated like a layout: an error names the
// file and the JSON path. The plan (the ordered list of trials with their names) is derived from
// the protocol and an optional counterbalancing seed, never stored separately, so a session's
// copy of the protocol is all that is needed to know what remains to be recorded.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/session/quality_thresholds.h"

namespace lmc {

// A block of trials recorded with one controller layout.
struct ProtocolLayout {
  std::string key;     // the trial-name prefix: "Naiv", "Opti" (core/processing/trial_tag.h)
  std::string layout;  // a preset name or a path relative to the protocol file
};

struct ProtocolPose {
  std::string key;  // "horizontal", "vertical" (the simulator's motion prefix)
  int code = 1;     // the pose digit of the trial name: 1 = horizontal, 2 = vertical
  std::string cue;  // what the subject does with the hand, e.g. "palm facing down"
};

struct TrialType {
  std::string key;         // the motion part of the trial name: "Static", "Index", "Thumb", "Wrist"
  std::string sim_motion;  // the simulator's motion: "static", "index", "thumb", "wrist"
  double duration_s = 10;
  std::string operator_cue;         // read by the operator
  std::string subject_cue;          // shown big to the subject
  std::vector<RomExpectation> rom;  // dynamic trials: the joint(s) that should move, and how far
  QualityThresholds quality;
};

// An optional calibration at the start of every layout block: a short trial of a
// still open hand from which the block's controllers are calibrated (core/calibration) before
// its first trial; the result becomes the block's layout in the manifest.
struct CalibrationStep {
  double duration_s = 5;  // 2…60
  std::string operator_cue = "Check every controller sees the hand; keep the hand still";
  std::string subject_cue = "Hold your open hand still above the controllers";
};

struct Protocol {
  std::string name;  // "study", "quick"
  std::string description;
  std::optional<CalibrationStep> calibration;  // absent: blocks start without one
  std::vector<ProtocolLayout> layouts;
  std::vector<ProtocolPose> poses;
  std::vector<TrialType> trial_types;
  int repetitions = 1;  // 1…99 (two digits in the trial name)
};

// One trial of the plan, in the order it is recorded.
struct PlannedTrial {
  int index = 0;           // position in the plan
  std::string name;        // e.g. "Naiv_Index102": <layout key>_<type key><pose code><repetition, 2 digits>
  std::string layout_key;  // the block: trials of one layout are recorded together
  int pose = 0;            // index into Protocol::poses
  int trial_type = 0;      // index into Protocol::trial_types
  int repetition = 1;
  std::string sim_motion;  // "<pose key>/<type sim_motion>", e.g. "vertical/index"
};

// Parses and validates; `source` names the file in errors ("study.json#/trial_types/2/duration_s").
Protocol protocol_from_json(const nlohmann::json& j, const std::string& source);
nlohmann::json protocol_to_json(const Protocol& protocol);

// The name of a block's calibration trial, attempt `attempt` (1…99): "Calib_<layout key>NN". It
// cannot be a plan name (those are <key>_<type>…), so the two never share files.
std::string calibration_trial_name(const std::string& layout_key, int attempt);

// A path, or a name of assets/protocols/ ("study", "quick").
Protocol load_protocol(const std::string& name_or_path);
// The file a name resolves to (for error messages and for resolving relative layout paths).
std::filesystem::path protocol_path(const std::string& name_or_path);
// The names of assets/protocols/*.json, sorted ("quick", "study"): what `protocol_path` accepts
// as a name, and what the Record tab offers.
std::vector<std::string> shipped_protocol_names();

// The study's block order — layout → pose → motion → repetitions — or, with a seed, the same
// blocks with the order of layouts, of poses within each layout and of motions within each pose
// shuffled (repetitions stay together and keep their numbers, so names do not change). The
// shuffle uses its own generator, so a seed gives the same order on every platform.
std::vector<PlannedTrial> plan_trials(const Protocol& protocol, std::optional<std::uint64_t> counterbalance_seed = {});

}  // namespace lmc
