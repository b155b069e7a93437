#include "core/session/session_folder.h"

#include <fstream>
#include <utility>
#include <vector>

#include "core/common/error.h"
#include "core/common/paths.h"
#include "core/common/safe_name.h"
#include "core/common/utc_time.h"
#include "core/io/atomic_write.h"
#include "core/io/layout_json.h"
#include "core/platform/file_lock.h"
#include "core/platform/process.h"
#include "core/session/trial_files.h"

namespace fs = std::filesystem;

namespace lmc {
namespace {

constexpr const char* kLockFile = ".lock";

// A protocol names each block's layout as a preset or a file; a file is relative to the protocol.
nlohmann::json resolve_layout(const std::string& ref, const fs::path& protocol_file) {
  const bool is_path = ref.find('/') != std::string::npos || fs::path(ref).extension() == ".json";
  if (!is_path) return layout_to_json(load_layout_or_preset(ref));
  fs::path p(ref);
  if (p.is_relative()) p = protocol_file.parent_path() / p;
  return layout_to_json(load_layout(p));
}

// Takes the folder's lock for this process; an error names the process that holds it.
platform::FileLock take_lock(const fs::path& dir) {
  std::string holder;
  platform::FileLock lock =
      platform::FileLock::take(dir / kLockFile, std::to_string(platform::current_process_id()), &holder);
  if (!lock.held())
    throw Error("session " + dir.string() + " is open in another process (pid " + holder +
                "); close it there first — two programs recording into one session would mix its trials");
  return lock;
}

bool lock_is_held(const fs::path& dir) {
  return platform::file_lock_is_held(dir / kLockFile);
}

std::string attempt_dir_name(const std::string& trial, int attempt) {
  return trial + ".attempt" + std::to_string(attempt);
}

}  // namespace

SessionState state_from_journal(const JournalContents& journal, const std::string& source) {
  if (journal.events.empty()) throw Error(ErrorLocation{source}, "the journal has no complete line: not a session");
  SessionState st;
  for (size_t k = 0; k < journal.events.size(); ++k)
    apply_journal_event(st, journal.events[k], source + ":" + std::to_string(journal.lines[k]));
  for (const auto& w : journal.warnings) st.warnings.push_back(w);
  return st;
}

fs::path default_session_dir(const std::string& subject_id) {
  return default_session_dir(subject_id, sessions_dir());
}

fs::path default_session_dir(const std::string& subject_id, const fs::path& root) {
  require_safe_name(subject_id, "subject id");
  return root / (subject_id + "-" + utc_now_compact());
}

SessionFolder::SessionFolder(fs::path dir, SessionState state, JournalWriter journal, platform::FileLock lock)
    : dir_(std::move(dir)), state_(std::move(state)), journal_(std::move(journal)), lock_(std::move(lock)) {}

SessionFolder::SessionFolder(SessionFolder&& o) noexcept
    : dir_(std::move(o.dir_)),
      state_(std::move(o.state_)),
      journal_(std::move(o.journal_)),
      manifest_(std::move(o.manifest_)),
      lock_(std::move(o.lock_)),
      recovered_(std::move(o.recovered_)) {}

SessionFolder::~SessionFolder() {
  if (!lock_.held()) return;
  // A clean close leaves no lock file behind (take_lock copes with one removed under it); a crash
  // leaves it, unlocked, and the next open takes it.
  std::error_code ec;
  fs::remove(dir_ / kLockFile, ec);
  lock_.release();
}

SessionFolder SessionFolder::create(const fs::path& dir, const NewSessionSpec& spec) {
  require_safe_name(spec.subject.subject_id, "subject id");
  std::error_code ec;
  if (fs::exists(dir, ec) && !(fs::is_directory(dir, ec) && fs::is_empty(dir, ec)))
    throw Error(ErrorLocation{dir.string()},
                "exists and is not an empty folder; a new session needs a folder of its own");
  const fs::path protocol_file = protocol_path(spec.protocol);
  Protocol protocol = load_protocol(spec.protocol);
  if (spec.duration_override_s) {
    if (!(*spec.duration_override_s > 0 && *spec.duration_override_s <= 3600))
      throw Error("a trial length must be more than 0 and at most 3600 s");
    for (auto& t : protocol.trial_types) t.duration_s = *spec.duration_override_s;
  }
  SessionSetup setup;
  setup.subject = spec.subject;
  setup.operator_name = spec.operator_name;
  setup.notes = spec.notes;
  setup.protocol = protocol_to_json(protocol);
  for (const auto& l : protocol.layouts) setup.layouts[l.key] = resolve_layout(l.layout, protocol_file);
  setup.vicon = spec.vicon;
  setup.counterbalance_seed = spec.counterbalance_seed;
  setup.software_version = LMC_VERSION;
  setup.created_utc = utc_now_iso8601();
  // Validate everything (subject, sizes, Vicon fields) through the reader a reopen uses, before a
  // folder exists: a refused session leaves nothing behind.
  const nlohmann::json setup_json = session_setup_to_json(setup);
  SessionState state = initial_state(session_setup_from_json(setup_json, "the new session"), "the new session");

  fs::create_directories(dir, ec);
  if (ec) throw Error(ErrorLocation{dir.string()}, "cannot create the session folder: " + ec.message());
  platform::FileLock lock = take_lock(dir);
  JournalWriter journal(dir / kJournalFile, true);
  SessionFolder folder(dir, SessionState{}, std::move(journal), std::move(lock));
  folder.record({{"type", "session_created"}, {"setup", setup_json}});
  return folder;
}

SessionFolder SessionFolder::open(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec))
    throw Error(ErrorLocation{dir.string()}, "no such folder: check the path (a typo, or a drive not mounted)");
  if (!fs::is_directory(dir, ec))
    throw Error(ErrorLocation{dir.string()}, "a file, not a folder: a subject session is a folder");
  if (!is_session_folder(dir))
    throw Error(ErrorLocation{dir.string()},
                std::string("not a subject session (no ") + kJournalFile + "); create one with `lmc session new`");
  // Released by its destructor when anything below throws.
  platform::FileLock lock = take_lock(dir);
  const fs::path path = dir / kJournalFile;
  JournalContents journal = read_journal(path);
  if (journal.cut_last_line) {
    // Keep the fragment for the record, then cut the journal back to its last complete line
    // so the next event starts on a line of its own.
    std::string fragment;
    {
      std::ifstream in(path, std::ios::binary);
      in.seekg(static_cast<std::streamoff>(journal.complete_bytes));
      fragment.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    write_file_atomically(dir / ("journal.cut-" + utc_now_compact() + ".txt"), fragment);
    std::error_code cut_ec;
    fs::resize_file(path, journal.complete_bytes, cut_ec);
    if (cut_ec)
      throw Error(ErrorLocation{path.string()}, "cannot cut the journal's broken last line: " + cut_ec.message());
  }
  SessionState state = state_from_journal(journal, path.string());
  SessionFolder folder(dir, std::move(state), JournalWriter(path, false), std::move(lock));
  folder.record(
      {{"type", "session_opened"}, {"software_version", LMC_VERSION}, {"pid", platform::current_process_id()}});
  // Collected first: record() replaces the state the loop would otherwise be walking.
  std::vector<std::pair<int, int>> cut_off;  // trial index, attempt
  for (const auto& t : folder.state().trials)
    if (t.status == TrialStatus::kRecording) cut_off.emplace_back(t.plan.index, t.attempts.back().number);
  for (const auto& [index, attempt] : cut_off) {
    const std::string name = folder.state().trials.at(static_cast<size_t>(index)).plan.name;
    folder.recovered_.push_back(name);
    folder.record({{"type", "trial_interrupted"},
                   {"trial", index},
                   {"name", name},
                   {"attempt", attempt},
                   {"reason",
                    "the program stopped while recording (crash, kill or power loss); the rows written "
                    "until then are kept"}});
  }
  return folder;
}

void SessionFolder::record(nlohmann::json event) {
  event["seq"] = state_.events + 1;
  event["utc"] = utc_now_iso8601();
  // Apply to a copy first: an event the state refuses never reaches the journal.
  SessionState next = state_;
  apply_journal_event(next, event, (dir_ / kJournalFile).string() + " (new event)");
  journal_.append(event);
  state_ = std::move(next);
  write_manifest(trial_changed_by(event));
}

void SessionFolder::write_manifest(int changed_trial) {
  write_file_atomically(dir_ / kManifestFile, manifest_.render(state_, changed_trial) + "\n");
}

void SessionFolder::require_trial(int i) const {
  if (i < 0 || i >= static_cast<int>(state_.trials.size()))
    throw Error("no trial " + std::to_string(i) + " in the plan of " + dir_.string());
}

int SessionFolder::last_attempt(int i) const {
  require_trial(i);
  const auto& t = state_.trials[static_cast<size_t>(i)];
  if (t.attempts.empty()) throw Error("trial " + t.plan.name + " has not been recorded yet");
  return t.attempts.back().number;
}

void SessionFolder::preflight(const std::string& block, bool ok, const nlohmann::json& report) {
  record({{"type", "preflight"}, {"block", block}, {"ok", ok}, {"report", report}});
}

void SessionFolder::preflight_override(const std::string& block, const std::string& reason) {
  if (reason.empty()) throw Error("overriding the pre-flight needs a reason (it goes into the journal)");
  record({{"type", "preflight_override"}, {"block", block}, {"reason", reason}});
}

int SessionFolder::calibration_started(const std::string& block) {
  if (!state_.protocol.calibration) throw Error("the session's protocol has no calibration step");
  if (!state_.setup.layouts.contains(block)) throw Error("the session has no layout block '" + block + "'");
  const auto it = state_.calibration.find(block);
  const int attempt = (it == state_.calibration.end() ? 0 : it->second.attempt) + 1;
  if (attempt > 99) throw Error("block " + block + " has been calibrated 99 times; keep its nominal layout");
  record({{"type", "calibration_started"},
          {"block", block},
          {"attempt", attempt},
          {"trial", calibration_trial_name(block, attempt)}});
  return attempt;
}

void SessionFolder::calibration_applied(const std::string& block, int attempt, const nlohmann::json& layout,
                                        const nlohmann::json& summary) {
  record({{"type", "calibration_applied"},
          {"block", block},
          {"attempt", attempt},
          {"layout", layout},
          {"summary", summary}});
}

void SessionFolder::calibration_kept_nominal(const std::string& block, const std::string& reason,
                                             const nlohmann::json& summary) {
  if (reason.empty()) throw Error("keeping the nominal layout needs a reason (it goes into the journal)");
  nlohmann::json e = {{"type", "calibration_kept_nominal"}, {"block", block}, {"reason", reason}};
  if (!summary.is_null()) e["summary"] = summary;
  record(e);
}

int SessionFolder::trial_started(int i) {
  require_trial(i);
  const auto& t = state_.trials[static_cast<size_t>(i)];
  if (t.status == TrialStatus::kAccepted)
    throw Error("trial " + t.plan.name + " is accepted; redo it to record it again");
  if (t.status == TrialStatus::kRecording) throw Error("trial " + t.plan.name + " is already recording");
  if (!t.attempts.empty() && t.attempts.back().superseded_dir.empty())
    throw Error("trial " + t.plan.name + " still holds attempt " + std::to_string(t.attempts.back().number) +
                "; redo it first so that attempt is kept under superseded/");
  const int attempt = t.attempts.empty() ? 1 : t.attempts.back().number + 1;
  record({{"type", "trial_started"}, {"trial", i}, {"name", t.plan.name}, {"attempt", attempt}});
  return attempt;
}

void SessionFolder::trial_stopped(int i, const std::string& outcome, const std::string& reason,
                                  const std::string& go_utc) {
  const int a = last_attempt(i);
  nlohmann::json e = {{"type", "trial_stopped"},
                      {"trial", i},
                      {"name", state_.trials[static_cast<size_t>(i)].plan.name},
                      {"attempt", a},
                      {"outcome", outcome},
                      {"reason", reason}};
  if (!go_utc.empty()) e["go_utc"] = go_utc;
  record(e);
}

void SessionFolder::trial_verdict(int i, const nlohmann::json& quality) {
  const int a = last_attempt(i);
  record({{"type", "trial_verdict"},
          {"trial", i},
          {"name", state_.trials[static_cast<size_t>(i)].plan.name},
          {"attempt", a},
          {"quality", quality}});
}

void SessionFolder::trial_accepted(int i) {
  const int a = last_attempt(i);
  const auto& t = state_.trials[static_cast<size_t>(i)];
  if (t.status == TrialStatus::kRecording) throw Error("trial " + t.plan.name + " is still recording");
  if (!t.attempts.back().superseded_dir.empty())
    throw Error("trial " + t.plan.name + " has no current attempt to accept");
  record({{"type", "trial_accepted"}, {"trial", i}, {"name", t.plan.name}, {"attempt", a}});
}

void SessionFolder::redo(int i) {
  const int a = last_attempt(i);
  const auto& t = state_.trials[static_cast<size_t>(i)];
  if (t.status == TrialStatus::kRecording) throw Error("trial " + t.plan.name + " is recording; stop it first");
  if (!t.attempts.back().superseded_dir.empty()) return;  // already moved aside
  // With '/' on every system: the journal names it, and a session folder moves between systems.
  const std::string rel = (fs::path("superseded") / attempt_dir_name(t.plan.name, a)).generic_string();
  const fs::path target = dir_ / rel;
  std::error_code ec;
  fs::create_directories(target, ec);
  if (ec)
    throw Error(ErrorLocation{target.string()}, "cannot create the folder for the earlier attempt: " + ec.message());
  for (const fs::path& src : trial_files(dir_, t.plan.name).all()) {
    if (!fs::exists(src, ec)) continue;
    const fs::path dest = target / src.filename();
    if (fs::exists(dest, ec))
      throw Error(ErrorLocation{dest.string()},
                  "exists already; the earlier attempt is not overwritten (move it away by hand)");
    fs::rename(src, dest, ec);
    if (ec) throw Error(ErrorLocation{src.string()}, "cannot move the earlier attempt aside: " + ec.message());
  }
  record({{"type", "trial_redone"}, {"trial", i}, {"name", t.plan.name}, {"attempt", a}, {"superseded_dir", rel}});
}

void SessionFolder::note(int i, const std::string& text) {
  if (text.empty()) return;
  nlohmann::json e = {{"type", "note"}, {"text", text}};
  if (i >= 0) {
    require_trial(i);
    e["trial"] = i;
    e["name"] = state_.trials[static_cast<size_t>(i)].plan.name;
  }
  record(e);
}

void SessionFolder::device_event(const std::string& slot, const std::string& message) {
  record({{"type", "device_event"}, {"slot", slot}, {"message", message}});
}

SessionState read_session_state(const fs::path& dir) {
  if (!is_session_folder(dir))
    throw Error(ErrorLocation{dir.string()}, std::string("not a subject session (no ") + kJournalFile + ")");
  const fs::path journal = dir / kJournalFile;
  SessionState st = state_from_journal(read_journal(journal), journal.string());
  if (!lock_is_held(dir)) {
    for (auto& t : st.trials) {
      if (t.status != TrialStatus::kRecording) continue;
      t.status = TrialStatus::kInterrupted;
      st.warnings.push_back("trial " + t.plan.name +
                            " was recording when its program stopped; `lmc session run` marks it "
                            "interrupted and records it again");
    }
  }
  return st;
}

bool is_session_folder(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / kJournalFile, ec);
}

}  // namespace lmc
