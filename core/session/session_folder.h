#pragma once
// One subject session on disk (sessions/README.md):
//   session.json    the manifest, rewritten atomically after every event (a view of the journal)
//   journal.jsonl   every state change, appended and fsynced before anything acts on it
//   LMC_<T>.*, T.trc the accepted or latest attempt of each trial, under the trial's own name
//   superseded/T.attemptN/  earlier attempts, moved aside by a redo, never deleted
//   .lock           held (flock) by the one process running the session
// Opening replays the journal (it wins over the manifest), marks a trial that was recording
// when a process died as interrupted, and rewrites the manifest. Nothing here deletes a file.
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/platform/file_lock.h"
#include "core/session/manifest_text.h"
#include "core/session/session_journal.h"
#include "core/session/session_state.h"

namespace lmc {

// What `lmc session new` (or the Record tab's set-up) asks for.
struct NewSessionSpec {
  SubjectInfo subject;
  std::string operator_name;
  std::string notes;
  std::string protocol = "study";             // a name of assets/protocols/ or a path
  std::optional<double> duration_override_s;  // every trial this long (demos, tests)
  nlohmann::json vicon;                       // null or {host, port, database_path}
  std::optional<std::uint64_t> counterbalance_seed;
};

// The default folder of a new session: <sessions dir>/<subject>-<UTC date-time>.
std::filesystem::path default_session_dir(const std::string& subject_id);
// The same under `root` (the folder the operator chose for sessions).
std::filesystem::path default_session_dir(const std::string& subject_id, const std::filesystem::path& root);

// The session's state as its journal's events make it (the journal wins over the manifest);
// `source` names the journal in messages. Opening a folder and the fuzzer both use this.
SessionState state_from_journal(const JournalContents& journal, const std::string& source);

class SessionFolder {
 public:
  // Creates `dir` (which must not exist or be empty), copies the protocol and every layout it
  // uses into the manifest and journals session_created. Throws lmc::Error with what to fix.
  static SessionFolder create(const std::filesystem::path& dir, const NewSessionSpec& spec);
  // Opens for running: takes the folder's lock (an error names the holder when another process
  // runs it), replays the journal, marks interrupted trials and rewrites the manifest.
  static SessionFolder open(const std::filesystem::path& dir);

  SessionFolder(SessionFolder&&) noexcept;
  SessionFolder& operator=(SessionFolder&&) = delete;
  ~SessionFolder();

  const std::filesystem::path& dir() const { return dir_; }
  const SessionState& state() const { return state_; }
  // Trials found interrupted when this process opened the folder (names), for the operator.
  const std::vector<std::string>& recovered() const { return recovered_; }

  // Appends an event (type and fields; seq and utc are added), applies it, rewrites the manifest.
  void record(nlohmann::json event);

  void preflight(const std::string& block, bool ok, const nlohmann::json& report);
  void preflight_override(const std::string& block, const std::string& reason);
  // Journals the start of a new attempt of trial `i` and returns its number (1, 2, …).
  int trial_started(int i);
  // `go_utc`: when the subject was told to go, the start of what the trial's file holds ("" when
  // the trial never got there).
  void trial_stopped(int i, const std::string& outcome, const std::string& reason, const std::string& go_utc = {});
  void trial_verdict(int i, const nlohmann::json& quality);
  void trial_accepted(int i);
  // Moves the last attempt's files of trial `i` under superseded/<name>.attempt<N>/ and makes the
  // trial pending again. Safe to repeat after a crash half-way (files already moved stay moved).
  void redo(int i);
  void note(int i, const std::string& text);  // i = -1: a note on the whole session
  void device_event(const std::string& slot, const std::string& message);

  // A block's calibration step (Protocol::calibration). Started returns the new attempt's number;
  // its trial files are named calibration_trial_name(block, attempt), never reused. Applied makes
  // `layout` the block's layout in the manifest (the nominal one is kept beside it); kept-nominal
  // goes back to the layout the block was created with.
  int calibration_started(const std::string& block);
  void calibration_applied(const std::string& block, int attempt, const nlohmann::json& layout,
                           const nlohmann::json& summary);
  void calibration_kept_nominal(const std::string& block, const std::string& reason, const nlohmann::json& summary);

 private:
  SessionFolder(std::filesystem::path dir, SessionState state, JournalWriter journal, platform::FileLock lock);
  void write_manifest(int changed_trial);
  void require_trial(int i) const;
  int last_attempt(int i) const;

  std::filesystem::path dir_;
  SessionState state_;
  JournalWriter journal_;
  ManifestText manifest_;  // session.json's text, each trial's entry kept until an event changes it
  platform::FileLock lock_;
  std::vector<std::string> recovered_;
};

// Reads a session without changing anything (no lock, no repair, no manifest rewrite): for
// `lmc session status`, `lmc process` and the Review tab. A trial still "recording" is shown as
// interrupted unless a process holds the folder's lock right now.
SessionState read_session_state(const std::filesystem::path& dir);

// True when `dir` holds a subject session (its journal).
bool is_session_folder(const std::filesystem::path& dir);

inline constexpr const char* kJournalFile = "journal.jsonl";
inline constexpr const char* kManifestFile = "session.json";

}  // namespace lmc
