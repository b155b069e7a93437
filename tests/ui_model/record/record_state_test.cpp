// The Record tab's model without ImGui: a quick session on the simulated rig in simulated time —
// pre-flight, trials on the worker thread with live snapshots, pass/warn accepted, a redo kept as a
// superseded attempt, Stop interrupting a trial, actions refused while busy, and the resume notice.
// Waits poll with a generous deadline, never a fixed sleep.
#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <thread>

#include <gtest/gtest.h>

#include "core/io/lmc_recording.h"
#include "core/io/recorder_sidecar.h"
#include "core/session/session_folder.h"
#include "core/session/trial_files.h"
#include "tests/support/scratch_dir.h"
#include "ui/model/record/record_state.h"
#include "ui/model/record/subject_view.h"

namespace lmc::ui {
namespace record_model_test {  // named: test files share unity batches

namespace fs = std::filesystem;

RecordSettings fast_sim() {
  RecordSettings s;
  s.backend = "sim";
  s.fast = true;
  s.countdown_s = 0;
  return s;
}

NewSessionSpec quick(const std::string& subject = "S01") {
  NewSessionSpec spec;
  spec.subject.subject_id = subject;
  spec.protocol = "quick";
  return spec;
}

// Polls until `done` or the deadline; returns the status lines poll() gave.
std::vector<std::string> poll_until(RecordState& m, const std::function<bool()>& done, double timeout_s = 60) {
  std::vector<std::string> lines;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (auto line = m.poll(); !line.empty()) lines.push_back(line.text);
    if (done()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return lines;
}

void clear_preflight(RecordState& m) {
  ASSERT_TRUE(m.needs_preflight());
  ASSERT_EQ(m.start_preflight(), "");
  poll_until(m, [&] { return !m.busy() && m.last_preflight().has_value(); });
  ASSERT_TRUE(m.last_preflight());
  ASSERT_TRUE(m.last_preflight()->ok()) << m.last_preflight()->failures().front();
  EXPECT_FALSE(m.needs_preflight());
}

void record_current(RecordState& m) {
  const int before = m.last_attempt() ? m.last_attempt()->attempt + 1000 * m.last_attempt()->trial : -1;
  ASSERT_EQ(m.start_trial(), "");
  EXPECT_TRUE(m.busy());
  poll_until(m, [&] {
    return !m.busy() && m.last_attempt() && m.last_attempt()->attempt + 1000 * m.last_attempt()->trial != before;
  });
  ASSERT_FALSE(m.busy());
}

TEST(RecordState, AQuickSessionRecordsBothTrialsAndAcceptsPassOrWarn) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordState m;
  ASSERT_EQ(m.create(dir, quick(), fast_sim()), "");
  ASSERT_EQ(m.state().trials.size(), 2U);
  EXPECT_EQ(m.current_trial(), 0);
  EXPECT_NE(m.start_trial(), "");  // refused before the pre-flight
  clear_preflight(m);

  record_current(m);
  ASSERT_TRUE(m.last_attempt());
  EXPECT_EQ(m.last_attempt()->outcome, "completed");
  EXPECT_NE(m.last_attempt()->verdict(), "fail");
  EXPECT_EQ(m.state().trials[0].status, TrialStatus::kAccepted);
  EXPECT_EQ(m.current_trial(), 1);

  record_current(m);
  EXPECT_TRUE(m.finished());
  EXPECT_EQ(m.accepted_count(), 2);
  // The folder agrees with the model's copy (read as `lmc session status` would).
  const auto on_disk = read_session_state(dir);
  EXPECT_EQ(on_disk.count(TrialStatus::kAccepted), 2);
  m.close();
  fs::remove_all(dir);
}

TEST(RecordState, RedoKeepsTheEarlierAttemptAndRecordsTheTrialAgain) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordState m;
  ASSERT_EQ(m.create(dir, quick(), fast_sim()), "");
  clear_preflight(m);
  record_current(m);
  ASSERT_EQ(m.redo(), "");
  EXPECT_EQ(m.current_trial(), 0);
  EXPECT_EQ(m.state().trials[0].status, TrialStatus::kPending);
  const auto& superseded = m.state().trials[0].attempts.at(0).superseded_dir;
  ASSERT_FALSE(superseded.empty());
  EXPECT_TRUE(fs::exists(dir / superseded / "LMC_Naiv_Static101.raw.txt"));
  record_current(m);
  EXPECT_EQ(m.state().trials[0].attempts.size(), 2U);
  EXPECT_EQ(m.state().trials[0].status, TrialStatus::kAccepted);
  EXPECT_TRUE(fs::exists(dir / "LMC_Naiv_Static101.raw.txt"));
  m.close();
  fs::remove_all(dir);
}

TEST(RecordState, RedoTakesTheRecordedTrialPickedInTheListBeforeTheLastOne) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordState m;
  ASSERT_EQ(m.create(dir, quick(), fast_sim()), "");
  clear_preflight(m);
  record_current(m);
  record_current(m);
  ASSERT_TRUE(m.finished());
  ASSERT_EQ(m.last_attempt()->trial, 1);
  m.select(0);  // the operator clicks the first trial, then presses R
  ASSERT_EQ(m.redo(), "");
  EXPECT_EQ(m.state().trials[0].status, TrialStatus::kPending);
  EXPECT_EQ(m.state().trials[1].status, TrialStatus::kAccepted);
  EXPECT_EQ(m.current_trial(), 0);
  m.close();
  fs::remove_all(dir);
}

TEST(RecordState, StopInterruptsTheTrialKeepsItsRowsAndWaitsForTheOperator) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordState m;
  RecordSettings real_time = fast_sim();
  real_time.fast = false;  // a 3 s trial in real time, stopped after its first frames
  ASSERT_EQ(m.create(dir, quick(), real_time), "");
  clear_preflight(m);
  ASSERT_EQ(m.start_trial(), "");
  EXPECT_NE(m.start_trial(), "");  // refused while busy
  EXPECT_NE(m.redo(0), "");
  poll_until(
      m, [&] { return m.live() && m.live()->recorder.frames_written > 20; }, 30);
  ASSERT_TRUE(m.live());
  EXPECT_TRUE(m.recording());
  m.stop_trial();
  poll_until(m, [&] { return !m.busy() && m.last_attempt().has_value(); });
  ASSERT_TRUE(m.last_attempt());
  EXPECT_EQ(m.last_attempt()->outcome, "interrupted");
  EXPECT_EQ(m.last_attempt()->verdict(), "fail");
  EXPECT_NE(m.state().trials[0].status, TrialStatus::kAccepted);
  EXPECT_EQ(m.current_trial(), 0);
  EXPECT_TRUE(fs::file_size(dir / "LMC_Naiv_Static101.raw.txt") > 1000);
  // The operator keeps it anyway: journaled, with a note saying so.
  ASSERT_EQ(m.accept_last(), "");
  EXPECT_EQ(m.state().trials[0].status, TrialStatus::kAccepted);
  ASSERT_FALSE(m.state().trials[0].notes.empty());
  EXPECT_NE(m.state().trials[0].notes.back().find("accepted by the operator"), std::string::npos);
  m.close();
  fs::remove_all(dir);
}

// The worker shares ownership of the folder, runner and live fusion it records through: a model
// taken down while a trial records (the workbench closing mid-trial) ends the trial on the
// worker, keeps its rows, and leaves a folder that opens again with the trial cut off and waiting.
TEST(RecordState, TakenDownMidTrialTheFolderOpensAgainWithTheTrialWaiting) {
  const fs::path dir = test::fresh_test_dir("record_model_teardown");
  RecordSettings real_time = fast_sim();
  real_time.fast = false;
  {
    auto m = std::make_unique<RecordState>();
    ASSERT_EQ(m->create(dir, quick(), real_time), "");
    clear_preflight(*m);
    ASSERT_EQ(m->start_trial(), "");
    poll_until(
        *m, [&] { return m->live() && m->live()->recorder.frames_written > 20; }, 30);
    ASSERT_TRUE(m->recording());
  }  // destroyed while the worker records
  EXPECT_TRUE(fs::file_size(dir / "LMC_Naiv_Static101.raw.txt") > 1000) << "the rows recorded so far are kept";
  RecordState again;
  ASSERT_EQ(again.open(dir, fast_sim()), "") << "the folder's lock went with the model";
  ASSERT_FALSE(again.state().trials.empty());
  EXPECT_NE(again.state().trials[0].status, TrialStatus::kAccepted);
  EXPECT_FALSE(again.state().trials[0].attempts.empty()) << "the cut-off attempt is in the journal";
  EXPECT_EQ(again.current_trial(), 0) << "and the trial waits to be recorded again";
  again.close();
  fs::remove_all(dir);
}

TEST(RecordState, OpeningAnotherProcesssSessionOrABadFolderSaysWhy) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordState a;
  ASSERT_EQ(a.create(dir, quick(), fast_sim()), "");
  RecordState b;
  const std::string locked = b.open(dir, fast_sim());
  EXPECT_NE(locked, "");  // the folder's lock is held by `a`
  EXPECT_FALSE(b.has_session());
  // A folder that is not a session, and one that does not exist (`--session` with a typo): each
  // says which it is.
  const fs::path empty_dir = test::fresh_test_dir("record_model_not_a_session");
  fs::create_directories(empty_dir);
  EXPECT_NE(b.open(empty_dir, fast_sim()).find("not a subject session"), std::string::npos);
  const std::string missing = b.open(dir / "nothing-here", fast_sim());
  EXPECT_NE(missing.find("no such folder"), std::string::npos) << missing;
  EXPECT_NE(missing.find((dir / "nothing-here").string()), std::string::npos) << missing;
  EXPECT_EQ(missing.find("lmc session new"), std::string::npos) << "it exists nowhere: creating is not the fix";
  fs::remove_all(empty_dir);
  RecordState c;
  EXPECT_NE(c.create(test::fresh_test_dir("record_model_bad"), quick("../escape"), fast_sim()).find("subject id"),
            std::string::npos);
  a.close();
  ASSERT_EQ(b.open(dir, fast_sim()), "");
  EXPECT_TRUE(b.recovered().empty());
  b.close();
  fs::remove_all(dir);
}

// A Space pressed while the pre-flight runs (the Record tab asks for another pre-flight) is
// answered with what is running and when Start comes, not a generic refusal; while a trial
// records, the answer says how to stop it.
TEST(RecordState, AnActionWhileBusySaysWhatRunsAndWhenToActAgain) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordState m;
  RecordSettings real_time = fast_sim();
  real_time.fast = false;  // a 3 s trial in real time: still recording when asked
  ASSERT_EQ(m.create(dir, quick(), real_time), "");
  ASSERT_EQ(m.start_preflight(), "");
  if (m.busy()) {  // the simulated pre-flight can finish before the next line on a fast machine
    EXPECT_TRUE(m.preflight_running());
    EXPECT_FALSE(m.recording());
    EXPECT_EQ(m.start_preflight(), "the pre-flight is still running; Start [Space] comes when every line is green");
  }
  poll_until(m, [&] { return !m.busy() && m.last_preflight().has_value(); });
  ASSERT_TRUE(m.last_preflight() && m.last_preflight()->ok());
  ASSERT_EQ(m.start_trial(), "");
  ASSERT_TRUE(m.recording());
  EXPECT_FALSE(m.preflight_running());
  EXPECT_EQ(m.start_trial(), "a trial is recording; stop it first (Space, or Esc to abort)");
  EXPECT_EQ(m.redo(0), "a trial is recording; stop it first (Space, or Esc to abort)");
  m.stop_trial();
  poll_until(m, [&] { return !m.busy() && m.last_attempt().has_value(); });
  m.close();
  fs::remove_all(dir);
}

TEST(RecordState, OverrideNeedsAReasonAndIsJournaled) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordState m;
  ASSERT_EQ(m.create(dir, quick(), fast_sim()), "");
  EXPECT_NE(m.override_preflight("  "), "");
  EXPECT_TRUE(m.needs_preflight());
  ASSERT_EQ(m.override_preflight("controllers checked by hand"), "");
  EXPECT_FALSE(m.needs_preflight());
  EXPECT_EQ(m.state().preflight_override.at("Naiv"), "controllers checked by hand");
  m.close();
  fs::remove_all(dir);
}

TEST(RecordState, ACalibratingProtocolCalibratesTheBlockBeforeItsFirstTrial) {
  const fs::path dir = test::fresh_test_dir("record_model_calibration");
  NewSessionSpec spec = quick("S09");
  spec.protocol = "study-calibrated";  // 5 s still hand before each block
  spec.duration_override_s = 1.0;
  RecordSettings settings = fast_sim();
  settings.sim.calibration_random_translation_mm = 20;
  RecordState m;
  ASSERT_EQ(m.create(dir, spec, settings), "");
  EXPECT_FALSE(m.needs_calibration()) << "the pre-flight comes first";
  clear_preflight(m);
  ASSERT_TRUE(m.needs_calibration());
  EXPECT_NE(m.start_trial(), "") << "a trial waits for the block's calibration";
  ASSERT_EQ(m.start_calibration(), "");
  EXPECT_TRUE(m.calibrating());
  poll_until(m, [&] { return !m.busy() && m.pending_calibration().has_value(); });
  ASSERT_TRUE(m.pending_calibration());
  ASSERT_TRUE(m.pending_calibration()->ok()) << m.pending_calibration()->failure;
  EXPECT_EQ(m.pending_calibration()->trial_name, "Calib_Naiv01");
  EXPECT_NE(m.keep_nominal_layout("  "), "") << "keeping the nominal layout needs a reason";
  ASSERT_EQ(m.apply_calibration(), "");
  EXPECT_FALSE(m.pending_calibration());
  EXPECT_FALSE(m.needs_calibration());
  EXPECT_EQ(m.state().calibration.at("Naiv").status, "applied");
  ASSERT_NE(m.current_layout(), nullptr);
  EXPECT_NE(m.current_layout()->name.find("calibrated"), std::string::npos) << m.current_layout()->name;
  record_current(m);
  EXPECT_EQ(m.last_attempt()->outcome, "completed");
}

TEST(RecordState, CloseAfterRecordingThenReopenAndCloseAgain) {
  const fs::path dir = test::fresh_test_dir("record_model_close");
  RecordState m;
  ASSERT_EQ(m.create(dir, quick(), fast_sim()), "");
  clear_preflight(m);
  record_current(m);
  ASSERT_TRUE(m.last_attempt());
  m.close();
  // Nothing of the closed session is left to be read against an empty trial list (the Record
  // tab drew the last verdict after Close and indexed trial 0 of none).
  EXPECT_FALSE(m.has_session());
  EXPECT_FALSE(m.last_attempt());
  EXPECT_FALSE(m.last_preflight());
  EXPECT_FALSE(m.live());
  EXPECT_EQ(m.note_trial(), -1);

  ASSERT_EQ(m.open(dir, fast_sim()), "");
  EXPECT_EQ(m.current_trial(), 1) << "the accepted first trial stays accepted";
  EXPECT_FALSE(m.last_attempt()) << "no trial recorded in this run yet";
  EXPECT_FALSE(m.resume_notice().empty());
  clear_preflight(m);
  record_current(m);
  EXPECT_TRUE(m.resume_notice().empty()) << "the notice described the folder as opened, before this attempt";
  EXPECT_TRUE(m.finished());
  m.close();
  EXPECT_FALSE(m.last_attempt());
  EXPECT_EQ(read_session_state(dir).count(TrialStatus::kAccepted), 2);

  // Opened complete ("nothing is left to record"), then a trial redone: the notice goes, it is no
  // longer true.
  ASSERT_EQ(m.open(dir, fast_sim()), "");
  ASSERT_FALSE(m.resume_notice().empty());
  ASSERT_EQ(m.redo(1), "");
  EXPECT_TRUE(m.resume_notice().empty()) << "the notice still said every trial was accepted";
  EXPECT_EQ(m.accepted_count(), 1);
  m.close();
  fs::remove_all(dir);
}

TEST(RecordState, ARealTimeTrialShowsTheCircleForItsWholeLengthFromGo) {
  const fs::path dir = test::fresh_test_dir("record_model_go");
  RecordState m;
  RecordSettings settings;
  settings.backend = "sim";
  settings.fast = false;  // real time: the countdown is the subject's
  settings.countdown_s = 1.0;
  NewSessionSpec spec = quick();
  spec.duration_override_s = 2.0;
  ASSERT_EQ(m.create(dir, spec, settings), "");
  clear_preflight(m);
  ASSERT_EQ(m.start_trial(), "");
  bool counted_down = false;
  double first_circle_s = -1, last_circle_s = -1, first_remaining_s = -1;
  std::vector<SubjectStage> stages;
  poll_until(m, [&] {
    const SubjectView v = build_subject_view(subject_view_inputs(m), 0.0);
    if (stages.empty() || stages.back() != v.stage) stages.push_back(v.stage);
    counted_down = counted_down || v.stage == SubjectStage::kCountdown;
    if (v.red_circle && m.live()) {
      if (first_circle_s < 0) {
        first_circle_s = m.live()->recording_s;
        first_remaining_s = m.live()->remaining_s;
      }
      last_circle_s = m.live()->recording_s;
    }
    return !m.busy() && m.last_attempt().has_value();
  });
  ASSERT_TRUE(m.last_attempt());
  EXPECT_EQ(m.last_attempt()->outcome, "completed") << m.last_attempt()->reason;
  EXPECT_TRUE(counted_down);
  // The circle appears at go and stays for the trial's two seconds (the subject screen showed
  // "3, 2, 1, Starting" and never the circle when the countdown ate the recording).
  EXPECT_GE(first_circle_s, 0.0);
  // The screen reads the trial about ten times a second; the margins allow a loaded machine.
  EXPECT_LE(first_circle_s, 0.5);
  EXPECT_GE(last_circle_s, 1.5);
  EXPECT_GE(first_remaining_s, 1.5) << "the status counts down the simulator's trial too (it said 0 s left)";

  // The journal's start, go and stop agree with the file: go is where the file starts.
  const auto st = read_session_state(dir);
  const auto& attempt = st.trials[0].attempts.at(0);
  ASSERT_FALSE(attempt.go_utc.empty());
  EXPECT_LE(attempt.started_utc, attempt.go_utc);
  EXPECT_LE(attempt.go_utc, attempt.stopped_utc);
  const auto files = lmc::trial_files(dir, st.trials[0].plan.name);
  const RecorderSidecar side = read_recorder_sidecar(files.sidecar);
  EXPECT_EQ(side.trial_window.at("go_host_utc").get<std::string>(), attempt.go_utc);
  EXPECT_DOUBLE_EQ(side.trial_window.at("countdown_s").get<double>(), 1.0);
  EXPECT_LE(side.host_start_utc, attempt.go_utc);
  EXPECT_LE(attempt.go_utc, side.host_stop_utc);
  std::map<int, std::pair<std::int64_t, std::int64_t>> span;
  for (const auto& row : read_lmc_recording(files.recording).rows) {
    auto [it, fresh] = span.try_emplace(row.device_id, row.timestamp_us, row.timestamp_us);
    it->second.first = std::min(it->second.first, row.timestamp_us);
    it->second.second = std::max(it->second.second, row.timestamp_us);
  }
  ASSERT_EQ(span.size(), 4u);
  for (const auto& [id, s] : span) {
    EXPECT_LE(s.second - s.first, 2'000'000) << "LMC" << id;
    EXPECT_GE(s.second - s.first, 2'000'000 - 2 * 91'000) << "LMC" << id << ": two seconds, less the edge frames";
  }
  m.close();
  fs::remove_all(dir);
}

}  // namespace record_model_test
}  // namespace lmc::ui
