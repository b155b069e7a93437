#pragma once
// What a subject session folder says: who, which protocol and layouts, and where each
// trial of the plan stands. The state is a pure function of the journal: replaying its events in
// order with apply_journal_event gives the same state every time, so after a crash the journal
// wins and the manifest (session_manifest_json of the state) can always be rebuilt from it.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/session/protocol.h"

namespace lmc {

// pending: never recorded (or redone); recording: an attempt started and has not stopped;
// recorded: stopped with a pass or warn verdict, waiting for the operator; interrupted: the
// program died while recording (the partial file is kept, the trial is queued for redo);
// failed: the last attempt's verdict was fail; accepted: done.
enum class TrialStatus { kPending, kRecording, kRecorded, kInterrupted, kFailed, kAccepted };
const char* trial_status_name(TrialStatus s);

struct AttemptState {
  int number = 0;  // 1, 2, …
  std::string started_utc, stopped_utc;
  std::string go_utc;   // when the subject was told to go: where the file starts ("" if never)
  std::string outcome;  // "" while recording; completed | aborted | failed | interrupted
  std::string reason;
  nlohmann::json quality;          // quality_to_json of its verdict, null until assessed
  std::string superseded_dir;      // relative to the session folder, once redone ("superseded/T.attempt1")
  std::vector<std::string> notes;  // the trial's notes journaled while this was its latest attempt
  std::string verdict() const;     // "pass" | "warn" | "fail" | "" (not assessed)
};

struct TrialState {
  PlannedTrial plan;
  TrialStatus status = TrialStatus::kPending;
  std::vector<AttemptState> attempts;
  std::vector<std::string> notes;
  const AttemptState* last_attempt() const { return attempts.empty() ? nullptr : &attempts.back(); }
};

// Empty when `mm` is a plausible hand length or breadth, else why not (the one rule for the
// manifest reader and the Record tab's form).
std::string hand_size_problem(double mm);

struct SubjectInfo {
  std::string subject_id;                 // pseudonymous; a safe name (core/common/safe_name.h)
  std::string handedness = "right";       // right | left
  std::optional<double> hand_length_mm;   // wrist crease to middle fingertip
  std::optional<double> hand_breadth_mm;  // across the metacarpal heads
};

// What `lmc session new` decides once; the journal's first event carries it.
struct SessionSetup {
  SubjectInfo subject;
  std::string operator_name;
  std::string notes;
  nlohmann::json protocol;                        // protocol_to_json of the protocol used (a copy)
  std::map<std::string, nlohmann::json> layouts;  // layout key → full layout JSON (a copy)
  nlohmann::json vicon;                           // null, or {host, port, database_path}
  std::optional<std::uint64_t> counterbalance_seed;
  std::string software_version;
  std::string created_utc;
};

nlohmann::json session_setup_to_json(const SessionSetup& setup);
// Validates (subject id, handedness, sizes, protocol, one layout per block); errors name `source`.
SessionSetup session_setup_from_json(const nlohmann::json& j, const std::string& source);

// Where a block's calibration step (Protocol::calibration) stands. `recording` after a crash means
// the step was cut off: it is done again. The block's layout in setup.layouts is the calibrated
// one once `applied`; the layout it was calibrated from stays in SessionState::nominal_layouts.
struct BlockCalibrationState {
  std::string status;  // "" (not yet) | recording | applied | nominal (the operator kept the nominal layout)
  int attempt = 0;     // the latest attempt (its trial is calibration_trial_name(block, attempt))
  std::string trial;
  nlohmann::json summary;  // per controller: correction, residual before/after, warnings (null until fitted)
  std::string reason;      // why the nominal layout was kept
  bool done() const { return status == "applied" || status == "nominal"; }
};

struct SessionState {
  SessionSetup setup;
  Protocol protocol;                                         // parsed from setup.protocol
  std::vector<TrialState> trials;                            // the plan, in order
  std::map<std::string, nlohmann::json> preflight;           // block → its latest pre-flight report
  std::map<std::string, std::string> preflight_override;     // block → the operator's reason
  std::map<std::string, BlockCalibrationState> calibration;  // block → its calibration step
  std::map<std::string, nlohmann::json> nominal_layouts;     // block → its layout before calibration
  int events = 0;                                            // journal events applied
  std::string last_event_utc;
  std::vector<std::string> warnings;  // e.g. a cut last journal line that was ignored

  const SubjectInfo& subject() const { return setup.subject; }
  // The first trial that is not accepted, or -1 when every trial is.
  int next_trial() const;
  int count(TrialStatus s) const;
  int trial_index(const std::string& name) const;  // -1 when not in the plan
};

// The state right after creation: every planned trial pending.
SessionState initial_state(const SessionSetup& setup, const std::string& source);

// Applies one journal event. `where` names the journal line for errors ("…/journal.jsonl:12").
// Unknown event types are kept out of the state with a warning, so a newer program's journal
// still opens.
void apply_journal_event(SessionState& state, const nlohmann::json& event, const std::string& where);

// The manifest `session.json`: the setup plus every trial's status, attempts and verdicts. It is
// manifest_json_without_trials plus "trials", one manifest_trial_json per planned trial
// (manifest_text.h assembles the same document from those parts).
nlohmann::json session_manifest_json(const SessionState& state);
nlohmann::json manifest_json_without_trials(const SessionState& state);
nlohmann::json manifest_trial_json(const SessionState& state, const TrialState& trial);

// Which trial's manifest entry a journal event can change once applied: its index, or one of these.
inline constexpr int kNoTrialChanged = -1;
inline constexpr int kAllTrialsChanged = -2;
int trial_changed_by(const nlohmann::json& event);

}  // namespace lmc
