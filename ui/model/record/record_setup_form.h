#pragma once
// The Record tab's set-up form as data: a new subject session (subject, hand, optional
// hand sizes, operator, notes, protocol from assets/protocols/, Vicon target and database, folder)
// or an existing session folder to resume, and how to record (backend, simulated time). The
// panel draws these fields and shows check_setup_form()'s problem under each; the spec is built
// by the same function `lmc session new` uses (devices/session_runner/new_session_spec.h), and every
// check calls the core rule it mirrors, so the form refuses exactly what the folder would.
#include <filesystem>
#include <string>
#include <vector>

#include "core/session/session_folder.h"
#include "devices/session_runner/new_session_spec.h"
#include "ui/model/record/record_state.h"

namespace lmc::ui {

// One shipped protocol: its name and a line saying what it records.
struct ProtocolChoice {
  std::string name;         // "study"
  std::string label;        // "study: 80 trials, 2 layouts"
  std::string description;  // the protocol's own words, or why it cannot be read
  bool readable = true;
};
// assets/protocols/*.json, sorted by name; a file that does not load is listed with its error.
std::vector<ProtocolChoice> protocol_choices();

struct RecordSetupForm {
  RecordSetupForm();  // reads the protocol choices; "study" selected when shipped

  char subject[65] = "S01";
  int handedness = 0;                             // 0 right, 1 left
  float hand_length_mm = 0, hand_breadth_mm = 0;  // 0: not measured
  char operator_name[64] = "";
  char notes[256] = "";
  std::vector<ProtocolChoice> protocols;
  int protocol = 0;  // index into protocols
  char vicon[128] = "";
  char vicon_database[256] = "";
  // Where sessions live (the resume list, new sessions' default folders): the user's data folder
  // (core/common/paths.h sessions_dir()) until the operator types another.
  char sessions_root[512] = "";
  char folder[512] = "";  // empty: <sessions_root>/<subject>-<time>
  char open_folder[512] = "";
  int backend = 0;  // 0 sim, 1 leapc
  bool fast = false;

  bool select_protocol(const std::string& name);
  std::string protocol_name() const;  // "" when none is shipped
  devices::NewSessionFields fields() const;
  // Throws lmc::Error (the form's problems are checked first by the tab).
  NewSessionSpec spec() const;
  std::filesystem::path new_session_dir() const;  // the folder, or the default for the subject
  std::filesystem::path sessions_folder() const;  // sessions_root as a path
  RecordSettings settings() const;
};

// What is wrong with each field (empty: fine). Create stays disabled while any is set.
struct SetupFormProblems {
  std::string subject, hand_length, hand_breadth, protocol, vicon, vicon_database, folder;
  bool any() const;
  std::string first() const;  // the first problem, for the status line
};
SetupFormProblems check_setup_form(const RecordSetupForm& form);

// A session folder found under a sessions directory, for the "resume" list.
struct SessionListing {
  std::filesystem::path dir;
  // The folder between the sessions directory and the session ("demo" for sessions/demo/S01);
  // empty for a session directly under it.
  std::string group;
  std::string subject, protocol;
  int accepted = 0, total = 0, interrupted = 0;
  std::string problem;  // set when the folder could not be read (the rest is empty)
  std::filesystem::file_time_type journal_written{};
};
// Every subject session under `root`: directly under it, and one level down in a folder that is
// not a session itself (sessions/demo/S01 — labs group sessions by study or cohort). Grouped by
// that folder: the sessions directly under `root` first, then each folder by name; within a
// group, the one whose journal was written last first. Read-only: nothing is locked or repaired.
std::vector<SessionListing> list_sessions(const std::filesystem::path& root);
// The Record tab's resume list: list_sessions(root), then the demo sessions scripts/run records
// (core/common/paths.h demo_sessions_dir()) under their folder's full path when that folder is
// not already in the list, so a lab that just ran the demo finds it where it looks.
std::vector<SessionListing> list_resumable_sessions(const std::filesystem::path& root);

// The listed sessions whose subject id is `subject`: a subject id is a person, so creating a new
// session with one of these ids asks first (continue that session, add a second session of the same
// subject, or choose another id). Most recent first, as listed.
std::vector<SessionListing> sessions_of_subject(const std::vector<SessionListing>& listed, const std::string& subject);
// The question's words: "Subject P01 already has 1 session here: …/P01-… (2 of 2 trials accepted)."
std::string subject_clash_text(const std::string& subject, const std::vector<SessionListing>& same);

}  // namespace lmc::ui
