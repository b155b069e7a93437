#include "core/session/session_folder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "core/common/error.h"
#include "core/session/session_trials.h"
#include "core/session/trial_files.h"
#include "tests/support/scratch_dir.h"

namespace fs = std::filesystem;

namespace lmc {
namespace {

using ::testing::HasSubstr;

NewSessionSpec quick_spec(const std::string& subject = "S01") {
  NewSessionSpec spec;
  spec.subject.subject_id = subject;
  spec.subject.hand_length_mm = 185;
  spec.protocol = "quick";
  spec.operator_name = "op";
  return spec;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

int count_lines(const fs::path& p) {
  const std::string t = read_text(p);
  return static_cast<int>(std::count(t.begin(), t.end(), '\n'));
}

void touch(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

TEST(SessionFolder, CreateWritesManifestJournalAndPlan) {
  const fs::path dir = test::fresh_test_dir("session");
  {
    SessionFolder f = SessionFolder::create(dir, quick_spec());
    EXPECT_EQ(f.state().trials.size(), 2u);
    EXPECT_EQ(f.state().next_trial(), 0);
    EXPECT_EQ(f.state().subject().subject_id, "S01");
    ASSERT_EQ(f.state().setup.layouts.count("Naiv"), 1u);
    EXPECT_EQ(f.state().setup.layouts.at("Naiv")["name"], "paper-initial");
  }
  EXPECT_EQ(count_lines(dir / kJournalFile), 1);
  const auto manifest = nlohmann::json::parse(read_text(dir / kManifestFile));
  EXPECT_EQ(manifest["format"], "lmc-subject-session");
  EXPECT_EQ(manifest["subject"]["id"], "S01");
  EXPECT_DOUBLE_EQ(manifest["subject"]["hand_length_mm"].get<double>(), 185.0);
  EXPECT_EQ(manifest["trials"][1]["name"], "Naiv_Index101");
  EXPECT_EQ(manifest["trials"][1]["status"], "pending");
  EXPECT_EQ(manifest["protocol"]["name"], "quick");
  EXPECT_TRUE(is_session_folder(dir));
  fs::remove_all(dir);
}

TEST(SessionFolder, RefusesUnsafeSubjectIdsAndLeavesNothingBehind) {
  const fs::path dir = test::fresh_test_dir("session");
  for (const std::string& bad : {std::string("../x"), std::string("a/b"), std::string("a\0b", 3), std::string(200, 'a'),
                                 std::string(""), std::string("-x")}) {
    try {
      SessionFolder::create(dir, quick_spec(bad));
      ADD_FAILURE() << "accepted subject id of length " << bad.size();
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr("subject id"));
    }
    EXPECT_FALSE(fs::exists(dir));
  }
}

TEST(SessionFolder, RefusesAFolderThatHoldsFiles) {
  const fs::path dir = test::fresh_test_dir("session");
  fs::create_directories(dir);
  touch(dir / "x.txt", "x");
  EXPECT_THROW(SessionFolder::create(dir, quick_spec()), Error);
  EXPECT_FALSE(fs::exists(dir / kJournalFile));
  fs::remove_all(dir);
}

TEST(SessionFolder, TrialLifecycleSurvivesReopening) {
  const fs::path dir = test::fresh_test_dir("session");
  {
    SessionFolder f = SessionFolder::create(dir, quick_spec());
    EXPECT_EQ(f.trial_started(0), 1);
    f.trial_stopped(0, "completed", "");
    f.trial_verdict(0, {{"verdict", "warn"}, {"reasons", {"index finger unseen in 41 % of frames"}}});
    EXPECT_EQ(f.state().trials[0].status, TrialStatus::kRecorded);
    f.trial_accepted(0);
    f.note(0, "subject sneezed at 4 s");
    EXPECT_EQ(f.state().next_trial(), 1);
  }
  SessionFolder g = SessionFolder::open(dir);
  const TrialState& t = g.state().trials[0];
  EXPECT_EQ(t.status, TrialStatus::kAccepted);
  ASSERT_EQ(t.attempts.size(), 1u);
  EXPECT_EQ(t.attempts[0].verdict(), "warn");
  EXPECT_EQ(t.attempts[0].outcome, "completed");
  ASSERT_EQ(t.notes.size(), 1u);
  EXPECT_TRUE(g.recovered().empty());
  EXPECT_EQ(g.state().next_trial(), 1);
}

TEST(SessionFolder, NotesBelongToTheAttemptTheyWereTakenOnAndGoIsJournaled) {
  const fs::path dir = test::fresh_test_dir("session_attempt_notes");
  {
    SessionFolder f = SessionFolder::create(dir, quick_spec());
    f.note(0, "before any attempt");
    f.trial_started(0);
    f.trial_stopped(0, "completed", "", "2026-11-27T10:00:03.000Z");
    f.note(0, "glove slipped");
    f.redo(0);
    f.trial_started(0);
    f.trial_stopped(0, "completed", "", "2026-11-27T10:01:03.000Z");
  }
  const SessionFolder reopened = SessionFolder::open(dir);
  const TrialState& t = reopened.state().trials[0];
  ASSERT_EQ(t.attempts.size(), 2u);
  EXPECT_EQ(t.attempts[0].notes, (std::vector<std::string>{"glove slipped"}));
  EXPECT_TRUE(t.attempts[1].notes.empty()) << "attempt 1's note is not attempt 2's";
  EXPECT_EQ(t.notes.size(), 2u) << "the trial keeps every note";
  EXPECT_EQ(t.attempts[0].go_utc, "2026-11-27T10:00:03.000Z");
  EXPECT_EQ(t.attempts[1].go_utc, "2026-11-27T10:01:03.000Z");
}

// The manifest is assembled from each trial's kept text (manifest_text.h); after every kind of
// event it must be exactly the document session_manifest_json defines.
TEST(SessionFolder, TheManifestIsTheStatesDocumentAfterEveryKindOfEvent) {
  const fs::path dir = test::fresh_test_dir("session");
  SessionFolder f = SessionFolder::create(dir, quick_spec());
  int checked = 0;
  const auto expect_manifest = [&](const std::string& after) {
    EXPECT_EQ(read_text(dir / kManifestFile), session_manifest_json(f.state()).dump(2) + "\n") << "after " << after;
    ++checked;
  };
  expect_manifest("create");
  f.preflight("Naiv", true, {{"devices", 4}});
  expect_manifest("preflight");
  f.trial_started(0);
  expect_manifest("trial_started");
  f.device_event("LMC2", "unplugged");
  expect_manifest("device_event");
  f.trial_stopped(0, "completed", "");
  expect_manifest("trial_stopped");
  f.trial_verdict(0, {{"verdict", "warn"}, {"reasons", {"a line\nwith a break and \"quotes\""}}});
  expect_manifest("trial_verdict");
  f.trial_accepted(0);
  expect_manifest("trial_accepted");
  f.note(0, "subject sneezed at 4 s");
  expect_manifest("note on a trial");
  f.note(-1, "a note on the session");
  expect_manifest("note on the session");
  f.trial_started(1);
  f.trial_stopped(1, "failed", "LMC2 sent no frames");
  f.trial_verdict(1, {{"verdict", "fail"}, {"reasons", {"LMC2 sent no frames"}}});
  expect_manifest("a failed trial");
  f.redo(1);
  expect_manifest("redo");
  f.trial_started(1);
  expect_manifest("second attempt");
  {
    SessionFolder moved = std::move(f);  // the kept text moves with the folder
    moved.trial_stopped(1, "completed", "");
    EXPECT_EQ(read_text(dir / kManifestFile), session_manifest_json(moved.state()).dump(2) + "\n");
  }
  SessionFolder g = SessionFolder::open(dir);  // reopening journals session_opened and rewrites it
  EXPECT_EQ(read_text(dir / kManifestFile), session_manifest_json(g.state()).dump(2) + "\n");
  EXPECT_EQ(checked, 12);
}

TEST(SessionFolder, RedoKeepsTheEarlierAttemptUnderSuperseded) {
  const fs::path dir = test::fresh_test_dir("session");
  SessionFolder f = SessionFolder::create(dir, quick_spec());
  f.trial_started(1);
  const TrialFiles files = trial_files(dir, "Naiv_Index101");
  touch(files.recording, "attempt one rows\n");
  touch(files.sidecar, "{}");
  f.trial_stopped(1, "completed", "");
  f.trial_verdict(1, {{"verdict", "fail"}, {"reasons", {"LMC2 sent no frames"}}});
  EXPECT_EQ(f.state().trials[1].status, TrialStatus::kFailed);
  // A new attempt may not start over the files of the last one.
  EXPECT_THROW(f.trial_started(1), Error);
  f.redo(1);
  EXPECT_EQ(f.state().trials[1].status, TrialStatus::kPending);
  const fs::path kept = dir / "superseded" / "Naiv_Index101.attempt1";
  EXPECT_EQ(read_text(kept / "LMC_Naiv_Index101.raw.txt"), "attempt one rows\n");
  EXPECT_TRUE(fs::exists(kept / "LMC_Naiv_Index101.session.json"));
  EXPECT_FALSE(fs::exists(files.recording));
  EXPECT_EQ(f.state().trials[1].attempts[0].superseded_dir, "superseded/Naiv_Index101.attempt1");
  f.redo(1);  // repeating is harmless
  EXPECT_EQ(f.trial_started(1), 2);
}

TEST(SessionFolder, ACrashWhileRecordingIsMarkedInterruptedOnReopen) {
  const fs::path dir = test::fresh_test_dir("session");
  {
    SessionFolder f = SessionFolder::create(dir, quick_spec());
    f.trial_started(0);
    touch(trial_files(dir, "Naiv_Static101").recording, "partial\n");
  }  // the process "dies": no trial_stopped
  // Read-only view: no lock holder, so the trial shows as interrupted; nothing is written.
  const int lines_before = count_lines(dir / kJournalFile);
  const SessionState seen = read_session_state(dir);
  EXPECT_EQ(seen.trials[0].status, TrialStatus::kInterrupted);
  EXPECT_EQ(count_lines(dir / kJournalFile), lines_before);

  SessionFolder g = SessionFolder::open(dir);
  ASSERT_EQ(g.recovered().size(), 1u);
  EXPECT_EQ(g.recovered()[0], "Naiv_Static101");
  EXPECT_EQ(g.state().trials[0].status, TrialStatus::kInterrupted);
  EXPECT_EQ(g.state().trials[0].attempts[0].outcome, "interrupted");
  EXPECT_EQ(g.state().next_trial(), 0);
  EXPECT_THAT(read_text(dir / kJournalFile), HasSubstr("\"trial_interrupted\""));
  const auto manifest = nlohmann::json::parse(read_text(dir / kManifestFile));
  EXPECT_EQ(manifest["trials"][0]["status"], "interrupted");
  // The partial file is still there until a redo moves it aside.
  EXPECT_EQ(read_text(trial_files(dir, "Naiv_Static101").recording), "partial\n");
}

TEST(SessionFolder, ACutLastJournalLineIsSetAsideAndTheJournalGoesOn) {
  const fs::path dir = test::fresh_test_dir("session");
  { SessionFolder::create(dir, quick_spec()).trial_started(0); }
  { std::ofstream(dir / kJournalFile, std::ios::app) << "{\"type\":\"trial_stop"; }
  {
    SessionFolder f = SessionFolder::open(dir);
    EXPECT_FALSE(f.state().warnings.empty());
    f.note(-1, "after the crash");
  }
  const SessionState st = read_session_state(dir);
  EXPECT_EQ(st.trials[0].status, TrialStatus::kInterrupted);
  EXPECT_THAT(st.setup.notes, HasSubstr("after the crash"));
  bool fragment_kept = false;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind("journal.cut-", 0) == 0)
      fragment_kept = read_text(e.path()) == "{\"type\":\"trial_stop";
  EXPECT_TRUE(fragment_kept);
  fs::remove_all(dir);
}

TEST(SessionFolder, ABrokenLineInTheMiddleIsAnErrorNamingTheLine) {
  const fs::path dir = test::fresh_test_dir("session");
  { SessionFolder::create(dir, quick_spec()); }
  { std::ofstream(dir / kJournalFile, std::ios::app) << "not json\n{\"type\":\"note\",\"text\":\"x\"}\n"; }
  try {
    read_session_state(dir);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_THAT(e.what(), HasSubstr("journal.jsonl"));
  }
  fs::remove_all(dir);
}

TEST(SessionFolder, OneProcessAtATimeAndTheManifestIsRebuiltFromTheJournal) {
  const fs::path dir = test::fresh_test_dir("session");
  { SessionFolder::create(dir, quick_spec()).trial_started(0); }
  fs::remove(dir / kManifestFile);
  SessionFolder f = SessionFolder::open(dir);
  EXPECT_TRUE(fs::exists(dir / kManifestFile));
  try {
    SessionFolder::open(dir);
    ADD_FAILURE() << "a second runner was let in";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("open in another process"));
  }
  // While a runner holds the folder, a trial it is recording is shown as recording.
  f.trial_stopped(0, "interrupted", "x");
}

// A clean close leaves no lock file in the folder; the lock still keeps a second opener out while
// the folder is open, and the folder opens again after the close.
TEST(SessionFolder, ACleanCloseRemovesTheLockFile) {
  const fs::path dir = test::fresh_test_dir("session_lock");
  {
    SessionFolder f = SessionFolder::create(dir, quick_spec());
    EXPECT_TRUE(fs::exists(dir / ".lock"));
    EXPECT_THROW(SessionFolder::open(dir), Error);
  }
  EXPECT_FALSE(fs::exists(dir / ".lock")) << "a clean close left the lock behind";
  {
    SessionFolder again = SessionFolder::open(dir);
    EXPECT_TRUE(fs::exists(dir / ".lock"));
    EXPECT_THROW(SessionFolder::open(dir), Error);
  }
  EXPECT_FALSE(fs::exists(dir / ".lock"));
  fs::remove_all(dir);
}

TEST(SessionFolder, ProcessingTakesOnlyAcceptedAttempts) {
  const fs::path dir = test::fresh_test_dir("session");
  SessionFolder f = SessionFolder::create(dir, quick_spec());
  f.trial_started(0);
  touch(trial_files(dir, "Naiv_Static101").recording, "rows\n");
  f.trial_stopped(0, "completed", "");
  f.trial_verdict(0, {{"verdict", "pass"}, {"reasons", nlohmann::json::array()}});
  f.trial_accepted(0);
  f.trial_started(1);
  touch(trial_files(dir, "Naiv_Index101").recording, "rows\n");
  f.trial_stopped(1, "completed", "");
  std::vector<std::string> notes;
  const auto jobs = accepted_trial_jobs(dir, std::nullopt, &notes);
  ASSERT_EQ(jobs.size(), 1u);
  EXPECT_EQ(jobs[0].trial, "Naiv_Static101");
  ASSERT_TRUE(jobs[0].layout_json.has_value());
  EXPECT_EQ((*jobs[0].layout_json)["name"], "paper-initial");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("Naiv_Index101: recorded, not processed"));
}

}  // namespace
}  // namespace lmc
