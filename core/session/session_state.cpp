#include "core/session/session_state.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/common/safe_name.h"
#include "core/io/json_checked.h"
#include "core/io/layout_json.h"

namespace lmc {

const char* trial_status_name(TrialStatus s) {
  switch (s) {
    case TrialStatus::kPending:
      return "pending";
    case TrialStatus::kRecording:
      return "recording";
    case TrialStatus::kRecorded:
      return "recorded";
    case TrialStatus::kInterrupted:
      return "interrupted";
    case TrialStatus::kFailed:
      return "failed";
    case TrialStatus::kAccepted:
      return "accepted";
  }
  return "unknown";
}

std::string AttemptState::verdict() const {
  if (quality.is_object() && quality.contains("verdict") && quality["verdict"].is_string())
    return quality["verdict"].get<std::string>();
  return {};
}

nlohmann::json session_setup_to_json(const SessionSetup& s) {
  nlohmann::json subject = {{"id", s.subject.subject_id}, {"handedness", s.subject.handedness}};
  if (s.subject.hand_length_mm) subject["hand_length_mm"] = *s.subject.hand_length_mm;
  if (s.subject.hand_breadth_mm) subject["hand_breadth_mm"] = *s.subject.hand_breadth_mm;
  nlohmann::json layouts = nlohmann::json::object();
  for (const auto& [key, layout] : s.layouts) layouts[key] = layout;
  nlohmann::json j = {{"subject", subject},
                      {"operator", s.operator_name},
                      {"notes", s.notes},
                      {"protocol", s.protocol},
                      {"layouts", layouts},
                      {"vicon", s.vicon},
                      {"software_version", s.software_version},
                      {"created_utc", s.created_utc}};
  j["counterbalance_seed"] = s.counterbalance_seed ? nlohmann::json(*s.counterbalance_seed) : nlohmann::json(nullptr);
  return j;
}

namespace {

std::optional<double> optional_size_mm(const JsonReader& r, const char* key) {
  if (!r.has(key)) return std::nullopt;
  const JsonReader v = r.at(key);
  const double mm = v.number();
  if (auto why = hand_size_problem(mm); !why.empty()) v.fail(why);
  return mm;
}

}  // namespace

std::string hand_size_problem(double mm) {
  // Adult hands are 150–230 mm long and 65–105 mm broad; the bounds only catch typing slips
  // (cm for mm, a swapped field), not unusual hands.
  if (!(mm >= 30 && mm <= 400)) return "a hand size in mm between 30 and 400 was expected";
  return {};
}

SessionSetup session_setup_from_json(const nlohmann::json& j, const std::string& source) {
  const JsonReader r(j, source);
  r.only_keys({"subject", "operator", "notes", "protocol", "layouts", "vicon", "software_version", "created_utc",
               "counterbalance_seed"});
  SessionSetup s;
  const JsonReader subj = r.at("subject");
  subj.only_keys({"id", "handedness", "hand_length_mm", "hand_breadth_mm"});
  s.subject.subject_id = subj.string("id");
  if (auto why = safe_name_problem(s.subject.subject_id, "subject id"); !why.empty()) subj.at("id").fail(why);
  s.subject.handedness = subj.string_or("handedness", "right");
  if (s.subject.handedness != "right" && s.subject.handedness != "left")
    subj.at("handedness").fail("expected \"right\" or \"left\"");
  s.subject.hand_length_mm = optional_size_mm(subj, "hand_length_mm");
  s.subject.hand_breadth_mm = optional_size_mm(subj, "hand_breadth_mm");
  s.operator_name = r.string_or("operator", "");
  s.notes = r.string_or("notes", "");
  s.protocol = r.at("protocol").json();
  const JsonReader layouts = r.at("layouts");
  layouts.require_object();
  for (const auto& [key, value] : layouts.json().items()) s.layouts[key] = value;
  s.vicon = r.has("vicon") ? r.at("vicon").json() : nlohmann::json(nullptr);
  if (!s.vicon.is_null()) {
    const JsonReader v = r.at("vicon");
    v.only_keys({"host", "port", "database_path"});
    v.string("host");
    if (v.has("port")) {
      const int port = v.at("port").integer();
      if (port < 1 || port > 65535) v.at("port").fail("a UDP port 1…65535 was expected");
    }
  }
  s.software_version = r.string_or("software_version", "");
  s.created_utc = r.string_or("created_utc", "");
  if (r.has("counterbalance_seed")) {
    const auto& seed = r.at("counterbalance_seed").json();
    if (!seed.is_number_unsigned()) r.at("counterbalance_seed").fail("expected a non-negative integer");
    s.counterbalance_seed = seed.get<std::uint64_t>();
  }
  return s;
}

int SessionState::next_trial() const {
  for (const auto& t : trials)
    if (t.status != TrialStatus::kAccepted) return t.plan.index;
  return -1;
}

int SessionState::count(TrialStatus s) const {
  return static_cast<int>(
      std::count_if(trials.begin(), trials.end(), [s](const TrialState& t) { return t.status == s; }));
}

int SessionState::trial_index(const std::string& name) const {
  for (const auto& t : trials)
    if (t.plan.name == name) return t.plan.index;
  return -1;
}

SessionState initial_state(const SessionSetup& setup, const std::string& source) {
  SessionState st;
  st.setup = setup;
  st.protocol = protocol_from_json(setup.protocol, source + "#/protocol");
  for (const auto& l : st.protocol.layouts) {
    auto it = setup.layouts.find(l.key);
    if (it == setup.layouts.end())
      throw Error(ErrorLocation{source, 0, 0, "/layouts"}, "no layout for block '" + l.key + "'");
    layout_from_json(it->second, source + "#/layouts/" + l.key);  // validates the copy
  }
  for (const PlannedTrial& p : plan_trials(st.protocol, setup.counterbalance_seed)) {
    TrialState t;
    t.plan = p;
    st.trials.push_back(std::move(t));
  }
  return st;
}

namespace {

// The trial an event is about, checked against the plan: a journal that names a trial the plan
// does not have (another protocol, a hand edit) is refused rather than applied to the wrong one.
TrialState& event_trial(SessionState& st, const JsonReader& e) {
  const JsonReader idx = e.at("trial");
  const int i = idx.integer();
  if (i < 0 || i >= static_cast<int>(st.trials.size())) idx.fail("no trial " + std::to_string(i) + " in the plan");
  TrialState& t = st.trials[static_cast<size_t>(i)];
  if (e.has("name") && e.string("name") != t.plan.name)
    e.at("name").fail("trial " + std::to_string(i) + " of the plan is " + t.plan.name);
  return t;
}

// The block a calibration event is about, checked against the protocol's layouts.
std::string calibration_block(const SessionState& st, const JsonReader& e) {
  const std::string block = e.string("block");
  if (!st.setup.layouts.contains(block)) e.at("block").fail("the session has no layout block '" + block + "'");
  return block;
}

AttemptState& event_attempt(TrialState& t, const JsonReader& e) {
  const JsonReader a = e.at("attempt");
  const int n = a.integer();
  for (auto& at : t.attempts)
    if (at.number == n) return at;
  a.fail("trial " + t.plan.name + " has no attempt " + std::to_string(n));
}

// A trial's events (started, stopped, verdict, interrupted, accepted, redone) and notes; false
// when `type` is none of them.
bool apply_trial_event(SessionState& st, const std::string& type, const JsonReader& e, const std::string& utc) {
  if (type == "trial_started") {
    TrialState& t = event_trial(st, e);
    AttemptState a;
    a.number = e.at("attempt").integer();
    a.started_utc = utc;
    t.attempts.push_back(a);
    t.status = TrialStatus::kRecording;
  } else if (type == "trial_stopped") {
    TrialState& t = event_trial(st, e);
    AttemptState& a = event_attempt(t, e);
    a.outcome = e.string("outcome");
    a.reason = e.string_or("reason", "");
    a.go_utc = e.string_or("go_utc", "");
    a.stopped_utc = utc;
    t.status = TrialStatus::kRecorded;
  } else if (type == "trial_verdict") {
    TrialState& t = event_trial(st, e);
    AttemptState& a = event_attempt(t, e);
    a.quality = e.at("quality").json();
    t.status = a.verdict() == "fail" ? TrialStatus::kFailed : TrialStatus::kRecorded;
  } else if (type == "trial_interrupted") {
    TrialState& t = event_trial(st, e);
    AttemptState& a = event_attempt(t, e);
    a.outcome = "interrupted";
    a.reason = e.string_or("reason", "");
    t.status = TrialStatus::kInterrupted;
  } else if (type == "trial_accepted") {
    TrialState& t = event_trial(st, e);
    event_attempt(t, e);
    t.status = TrialStatus::kAccepted;
  } else if (type == "trial_redone") {
    TrialState& t = event_trial(st, e);
    AttemptState& a = event_attempt(t, e);
    a.superseded_dir = e.string("superseded_dir");
    t.status = TrialStatus::kPending;
  } else if (type == "note") {
    if (e.has("trial")) {
      TrialState& t = event_trial(st, e);
      t.notes.push_back(e.string("text"));
      if (!t.attempts.empty()) t.attempts.back().notes.push_back(e.string("text"));
    } else
      st.setup.notes += (st.setup.notes.empty() ? "" : "\n") + e.string("text");
  } else {
    return false;
  }
  return true;
}

// A block's calibration events (started, applied, kept nominal); false when `type` is none of them.
bool apply_calibration_event(SessionState& st, const std::string& type, const JsonReader& e, const std::string& where) {
  if (type == "calibration_started") {
    const std::string block = calibration_block(st, e);
    BlockCalibrationState& c = st.calibration[block];
    c.status = "recording";
    c.attempt = e.at("attempt").integer();
    c.trial = e.string("trial");
    c.summary = nullptr;
    c.reason.clear();
  } else if (type == "calibration_applied") {
    const std::string block = calibration_block(st, e);
    const JsonReader layout = e.at("layout");
    layout_from_json(layout.json(), where + "#/layout");  // validates it before it replaces the block's
    if (!st.nominal_layouts.contains(block)) st.nominal_layouts[block] = st.setup.layouts[block];
    st.setup.layouts[block] = layout.json();
    BlockCalibrationState& c = st.calibration[block];
    c.status = "applied";
    c.attempt = e.at("attempt").integer();
    c.summary = e.has("summary") ? e.at("summary").json() : nlohmann::json(nullptr);
  } else if (type == "calibration_kept_nominal") {
    const std::string block = calibration_block(st, e);
    // Back to the layout the block was created with, whatever an earlier calibration applied.
    if (auto it = st.nominal_layouts.find(block); it != st.nominal_layouts.end()) st.setup.layouts[block] = it->second;
    BlockCalibrationState& c = st.calibration[block];
    c.status = "nominal";
    c.reason = e.string_or("reason", "");
    if (e.has("summary")) c.summary = e.at("summary").json();
  } else {
    return false;
  }
  return true;
}

}  // namespace

void apply_journal_event(SessionState& st, const nlohmann::json& event, const std::string& where) {
  const JsonReader e(event, where);
  const std::string type = e.string("type");
  const std::string utc = e.string_or("utc", "");
  if (type == "session_created") {
    if (st.events != 0) e.at("type").fail("session_created appears after the first line");
    st = initial_state(session_setup_from_json(e.at("setup").json(), where + "#/setup"), where + "#/setup");
  } else if (st.events == 0) {
    e.at("type").fail("the journal must start with session_created");
  } else if (type == "preflight") {
    st.preflight[e.string("block")] = e.at("report").json();
  } else if (type == "preflight_override") {
    st.preflight_override[e.string("block")] = e.string("reason");
  } else if (apply_trial_event(st, type, e, utc) || apply_calibration_event(st, type, e, where)) {
    // Applied.
  } else if (type == "device_event" || type == "session_opened") {
    // Kept in the journal for the record; they do not change where trials stand.
  } else {
    st.warnings.push_back(where + ": unknown event type '" + type + "' ignored (written by a newer version?)");
  }
  ++st.events;
  if (!utc.empty()) st.last_event_utc = utc;
}

nlohmann::json manifest_trial_json(const SessionState& st, const TrialState& t) {
  const TrialType& type = st.protocol.trial_types[static_cast<size_t>(t.plan.trial_type)];
  nlohmann::json attempts = nlohmann::json::array();
  for (const auto& a : t.attempts) {
    nlohmann::json aj = {{"number", a.number},   {"started_utc", a.started_utc}, {"stopped_utc", a.stopped_utc},
                         {"outcome", a.outcome}, {"reason", a.reason},           {"verdict", a.verdict()},
                         {"quality", a.quality}};
    if (!a.go_utc.empty()) aj["go_utc"] = a.go_utc;
    if (!a.superseded_dir.empty()) aj["superseded_dir"] = a.superseded_dir;
    attempts.push_back(aj);
  }
  return {{"index", t.plan.index},
          {"name", t.plan.name},
          {"block", t.plan.layout_key},
          {"pose", st.protocol.poses[static_cast<size_t>(t.plan.pose)].key},
          {"motion", type.key},
          {"repetition", t.plan.repetition},
          {"duration_s", type.duration_s},
          {"status", trial_status_name(t.status)},
          {"attempts", attempts},
          {"notes", t.notes}};
}

nlohmann::json manifest_json_without_trials(const SessionState& st) {
  nlohmann::json j = {{"format", "lmc-subject-session"}, {"format_version", 1}};
  j.update(session_setup_to_json(st.setup));
  j["protocol_name"] = st.protocol.name;
  nlohmann::json pre = nlohmann::json::object();
  for (const auto& [block, report] : st.preflight) pre[block] = report;
  j["preflight"] = pre;
  nlohmann::json overrides = nlohmann::json::object();
  for (const auto& [block, reason] : st.preflight_override) overrides[block] = reason;
  j["preflight_override"] = overrides;
  if (st.protocol.calibration) {
    nlohmann::json cal = nlohmann::json::object();
    for (const auto& [block, c] : st.calibration) {
      cal[block] = {{"status", c.status}, {"attempt", c.attempt}, {"trial", c.trial}, {"summary", c.summary}};
      if (!c.reason.empty()) cal[block]["reason"] = c.reason;
    }
    j["calibration"] = cal;
    nlohmann::json nominal = nlohmann::json::object();
    for (const auto& [block, layout] : st.nominal_layouts) nominal[block] = layout;
    j["nominal_layouts"] = nominal;
  }
  j["journal_events"] = st.events;
  j["updated_utc"] = st.last_event_utc;
  return j;
}

nlohmann::json session_manifest_json(const SessionState& st) {
  nlohmann::json j = manifest_json_without_trials(st);
  nlohmann::json trials = nlohmann::json::array();
  for (const auto& t : st.trials) trials.push_back(manifest_trial_json(st, t));
  j["trials"] = trials;
  return j;
}

int trial_changed_by(const nlohmann::json& event) {
  const auto type = event.find("type");
  if (type == event.end() || !type->is_string()) return kAllTrialsChanged;
  const std::string& t = type->get_ref<const std::string&>();
  const auto trial = event.find("trial");
  const bool names_a_trial = trial != event.end() && trial->is_number_integer();
  // apply_journal_event changes a trial's entry only through event_trial(), i.e. for these events.
  if (t.rfind("trial_", 0) == 0 || t == "note") {
    if (names_a_trial) return trial->get<int>();
    return t == "note" ? kNoTrialChanged : kAllTrialsChanged;
  }
  if (t == "preflight" || t == "preflight_override" || t.rfind("calibration_", 0) == 0 || t == "device_event" ||
      t == "session_opened") {
    return kNoTrialChanged;
  }
  return kAllTrialsChanged;  // session_created, and anything this version does not know
}

}  // namespace lmc
