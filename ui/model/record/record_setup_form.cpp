#include "ui/model/record/record_setup_form.h"

#include <algorithm>
#include <cstdio>
#include <system_error>

#include "core/common/paths.h"
#include "core/common/safe_name.h"
#include "core/session/protocol.h"
#include "core/session/session_state.h"
#include "devices/vicon/vicon_trigger.h"

namespace lmc::ui {
namespace fs = std::filesystem;

std::vector<ProtocolChoice> protocol_choices() {
  std::vector<ProtocolChoice> out;
  for (const auto& name : shipped_protocol_names()) {
    ProtocolChoice c;
    c.name = name;
    c.label = name;
    try {
      const Protocol p = load_protocol(name);
      const size_t trials =
          p.layouts.size() * p.poses.size() * p.trial_types.size() * static_cast<size_t>(p.repetitions);
      c.label = name + ": " + std::to_string(trials) + " trials, " + std::to_string(p.layouts.size()) + " layout" +
                (p.layouts.size() == 1 ? "" : "s");
      c.description = p.description;
    } catch (const std::exception& e) {
      c.label = name + ": cannot be read";
      c.description = e.what();
      c.readable = false;
    }
    out.push_back(std::move(c));
  }
  return out;
}

RecordSetupForm::RecordSetupForm() : protocols(protocol_choices()) {
  select_protocol("study");
  std::snprintf(sessions_root, sizeof sessions_root, "%s", sessions_dir().string().c_str());
}

fs::path RecordSetupForm::sessions_folder() const {
  return sessions_root[0] != '\0' ? fs::path(sessions_root) : sessions_dir();
}

bool RecordSetupForm::select_protocol(const std::string& name) {
  for (size_t i = 0; i < protocols.size(); ++i) {
    if (protocols[i].name == name) {
      protocol = static_cast<int>(i);
      return true;
    }
  }
  return false;
}

std::string RecordSetupForm::protocol_name() const {
  return protocol >= 0 && protocol < static_cast<int>(protocols.size()) ? protocols[static_cast<size_t>(protocol)].name
                                                                        : std::string();
}

devices::NewSessionFields RecordSetupForm::fields() const {
  devices::NewSessionFields f;
  f.subject = subject;
  f.handedness = handedness == 0 ? "right" : "left";
  f.hand_length_mm = hand_length_mm;
  f.hand_breadth_mm = hand_breadth_mm;
  f.operator_name = operator_name;
  f.notes = notes;
  f.protocol = protocol_name();
  f.vicon = vicon;
  f.vicon_database = vicon_database;
  return f;
}

NewSessionSpec RecordSetupForm::spec() const {
  return devices::new_session_spec(fields());
}

fs::path RecordSetupForm::new_session_dir() const {
  return folder[0] != '\0' ? fs::path(folder) : default_session_dir(subject, sessions_folder());
}

RecordSettings RecordSetupForm::settings() const {
  RecordSettings r;
  r.backend = backend == 1 ? "leapc" : "sim";
  r.fast = fast && backend == 0;
  r.countdown_s = r.fast ? 0.0 : 3.0;
  // Real controllers are already open in the Devices tab's rig: a second LeapC connection to the
  // same devices would fight it, so sessions record through that hub.
  r.share_rig_hub = r.backend == "leapc";
  return r;
}

bool SetupFormProblems::any() const {
  return !first().empty();
}

std::string SetupFormProblems::first() const {
  for (const std::string* p : {&subject, &hand_length, &hand_breadth, &protocol, &vicon, &vicon_database, &folder})
    if (!p->empty()) return *p;
  return {};
}

SetupFormProblems check_setup_form(const RecordSetupForm& f) {
  SetupFormProblems p;
  p.subject = safe_name_problem(f.subject, "subject id");
  // 0 means "not measured"; anything else goes through the manifest's own rule.
  if (f.hand_length_mm != 0.0F) p.hand_length = hand_size_problem(f.hand_length_mm);
  if (f.hand_breadth_mm != 0.0F) p.hand_breadth = hand_size_problem(f.hand_breadth_mm);
  if (f.protocol_name().empty())
    p.protocol = "no protocol found in assets/protocols/";
  else if (const auto& chosen = f.protocols[static_cast<size_t>(f.protocol)]; !chosen.readable)
    p.protocol = chosen.label + ": " + chosen.description;
  if (f.vicon[0] != '\0') {
    try {
      (void)devices::parse_vicon_target(f.vicon);
    } catch (const std::exception& e) {
      p.vicon = e.what();
    }
  } else if (f.vicon_database[0] != '\0') {
    p.vicon_database = "a Vicon database needs a Vicon target (HOST[:PORT]) above";
  }
  if (f.folder[0] != '\0') {
    std::error_code ec;
    const fs::path dir(f.folder);
    if (fs::exists(dir, ec) && !(fs::is_directory(dir, ec) && fs::is_empty(dir, ec)))
      p.folder = dir.string() + " exists and is not an empty folder; a new session needs a folder of its own";
  }
  return p;
}

std::vector<SessionListing> list_sessions(const fs::path& root) {
  std::vector<SessionListing> out;
  std::error_code ec;
  const auto add = [&out, &ec](const fs::path& dir, const std::string& group) {
    SessionListing s;
    s.dir = dir;
    s.group = group;
    s.journal_written = fs::last_write_time(dir / kJournalFile, ec);
    try {
      const SessionState st = read_session_state(dir);
      s.subject = st.subject().subject_id;
      s.protocol = st.protocol.name;
      s.total = static_cast<int>(st.trials.size());
      s.accepted = st.count(TrialStatus::kAccepted);
      s.interrupted = st.count(TrialStatus::kInterrupted);
    } catch (const std::exception& ex) {
      s.problem = ex.what();
    }
    out.push_back(std::move(s));
  };
  for (const auto& e : fs::directory_iterator(root, ec)) {
    if (!e.is_directory(ec)) continue;
    if (is_session_folder(e.path())) {
      add(e.path(), "");
      continue;
    }
    // One level only: deeper folders are more likely to be copies, exports or caches than sessions.
    std::error_code inner_ec;
    for (const auto& inner : fs::directory_iterator(e.path(), inner_ec)) {
      if (inner.is_directory(inner_ec) && is_session_folder(inner.path()))
        add(inner.path(), e.path().filename().string());
    }
  }
  std::sort(out.begin(), out.end(), [](const SessionListing& a, const SessionListing& b) {
    if (a.group != b.group) return a.group < b.group;  // "" (directly under root) sorts first
    return a.journal_written > b.journal_written;
  });
  return out;
}

std::vector<SessionListing> list_resumable_sessions(const fs::path& root) {
  std::vector<SessionListing> out = list_sessions(root);
  std::error_code ec;
  const fs::path demo = demo_sessions_dir();
  const fs::path root_abs = fs::weakly_canonical(root, ec);
  const fs::path demo_abs = fs::weakly_canonical(demo, ec);
  // Already listed when the demo folder is the sessions folder or one of its folders.
  if (demo_abs == root_abs || demo_abs.parent_path() == root_abs) return out;
  for (SessionListing s : list_sessions(demo)) {
    if (!s.group.empty()) continue;  // the demo's own sessions, not folders further down
    s.group = demo.string();
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<SessionListing> sessions_of_subject(const std::vector<SessionListing>& listed, const std::string& subject) {
  std::vector<SessionListing> out;
  for (const auto& s : listed)
    if (s.problem.empty() && s.subject == subject) out.push_back(s);
  return out;
}

std::string subject_clash_text(const std::string& subject, const std::vector<SessionListing>& same) {
  std::string t = "Subject " + subject + " already has " + std::to_string(same.size()) + " session" +
                  (same.size() == 1 ? "" : "s") + ":";
  for (const auto& s : same)
    t += "\n  " + s.dir.string() + " (" + std::to_string(s.accepted) + " of " + std::to_string(s.total) +
         " trials accepted)";
  return t;
}

}  // namespace lmc::ui
