// The Record tab's model without ImGui: a quick session on the simulated rig in simulated time —
// pre-flight, trials on the worker thread with live snapshots, pass/warn accepted, a redo kept as a
// superseded attempt, Stop interrupting a trial, actions refused while busy, and the resume notice.
// Waits poll with a generous deadline, never a fixed sleep.
#include <chrono>
#include <filesystem>
#include <functional>
#include <thread>

#include <gtest/gtest.h>

#include "core/session/session_folder.h"
#include "tests/support/scratch_dir.h"
#include "ui/model/record/record_session_model.h"

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

session::NewSessionSpec quick(const std::string& subject = "S01") {
  session::NewSessionSpec spec;
  spec.subject.subject_id = subject;
  spec.protocol = "quick";
  return spec;
}

// Polls until `done` or the deadline; returns the status lines poll() gave.
std::vector<std::string> poll_until(RecordSessionModel& m, const std::function<bool()>& done, double timeout_s = 60) {
  std::vector<std::string> lines;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (auto line = m.poll(); !line.empty()) lines.push_back(line);
    if (done()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return lines;
}

void clear_preflight(RecordSessionModel& m) {
  ASSERT_TRUE(m.needs_preflight());
  ASSERT_EQ(m.start_preflight(), "");
  poll_until(m, [&] { return !m.busy() && m.last_preflight().has_value(); });
  ASSERT_TRUE(m.last_preflight());
  ASSERT_TRUE(m.last_preflight()->ok()) << m.last_preflight()->failures().front();
  EXPECT_FALSE(m.needs_preflight());
}

void record_current(RecordSessionModel& m) {
  const int before = m.last_attempt() ? m.last_attempt()->attempt + 1000 * m.last_attempt()->trial : -1;
  ASSERT_EQ(m.start_trial(), "");
  EXPECT_TRUE(m.busy());
  poll_until(m, [&] {
    return !m.busy() && m.last_attempt() && m.last_attempt()->attempt + 1000 * m.last_attempt()->trial != before;
  });
  ASSERT_FALSE(m.busy());
}

TEST(RecordSessionModel, AQuickSessionRecordsBothTrialsAndAcceptsPassOrWarn) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordSessionModel m;
  ASSERT_EQ(m.create(dir, quick(), fast_sim()), "");
  ASSERT_EQ(m.state().trials.size(), 2U);
  EXPECT_EQ(m.current_trial(), 0);
  EXPECT_NE(m.start_trial(), "");  // refused before the pre-flight
  clear_preflight(m);

  record_current(m);
  ASSERT_TRUE(m.last_attempt());
  EXPECT_EQ(m.last_attempt()->outcome, "completed");
  EXPECT_NE(m.last_attempt()->verdict(), "fail");
  EXPECT_EQ(m.state().trials[0].status, session::TrialStatus::kAccepted);
  EXPECT_EQ(m.current_trial(), 1);

  record_current(m);
  EXPECT_TRUE(m.finished());
  EXPECT_EQ(m.accepted_count(), 2);
  // The folder agrees with the model's copy (read as `lmc session status` would).
  const auto on_disk = session::read_session_state(dir);
  EXPECT_EQ(on_disk.count(session::TrialStatus::kAccepted), 2);
  m.close();
  fs::remove_all(dir);
}

TEST(RecordSessionModel, RedoKeepsTheEarlierAttemptAndRecordsTheTrialAgain) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordSessionModel m;
  ASSERT_EQ(m.create(dir, quick(), fast_sim()), "");
  clear_preflight(m);
  record_current(m);
  ASSERT_EQ(m.redo(), "");
  EXPECT_EQ(m.current_trial(), 0);
  EXPECT_EQ(m.state().trials[0].status, session::TrialStatus::kPending);
  const auto& superseded = m.state().trials[0].attempts.at(0).superseded_dir;
  ASSERT_FALSE(superseded.empty());
  EXPECT_TRUE(fs::exists(dir / superseded / "LMC_Naiv_Static101.raw.txt"));
  record_current(m);
  EXPECT_EQ(m.state().trials[0].attempts.size(), 2U);
  EXPECT_EQ(m.state().trials[0].status, session::TrialStatus::kAccepted);
  EXPECT_TRUE(fs::exists(dir / "LMC_Naiv_Static101.raw.txt"));
  m.close();
  fs::remove_all(dir);
}

TEST(RecordSessionModel, RedoTakesTheRecordedTrialPickedInTheListBeforeTheLastOne) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordSessionModel m;
  ASSERT_EQ(m.create(dir, quick(), fast_sim()), "");
  clear_preflight(m);
  record_current(m);
  record_current(m);
  ASSERT_TRUE(m.finished());
  ASSERT_EQ(m.last_attempt()->trial, 1);
  m.select(0);  // the operator clicks the first trial, then presses R
  ASSERT_EQ(m.redo(), "");
  EXPECT_EQ(m.state().trials[0].status, session::TrialStatus::kPending);
  EXPECT_EQ(m.state().trials[1].status, session::TrialStatus::kAccepted);
  EXPECT_EQ(m.current_trial(), 0);
  m.close();
  fs::remove_all(dir);
}

TEST(RecordSessionModel, StopInterruptsTheTrialKeepsItsRowsAndWaitsForTheOperator) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordSessionModel m;
  RecordSettings real_time = fast_sim();
  real_time.fast = false;  // a 3 s trial in real time, stopped after its first frames
  ASSERT_EQ(m.create(dir, quick(), real_time), "");
  clear_preflight(m);
  ASSERT_EQ(m.start_trial(), "");
  EXPECT_NE(m.start_trial(), "");  // refused while busy
  EXPECT_NE(m.redo(0), "");
  poll_until(m, [&] { return m.live() && m.live()->recorder.frames_written > 20; }, 30);
  ASSERT_TRUE(m.live());
  EXPECT_TRUE(m.recording());
  m.stop_trial();
  poll_until(m, [&] { return !m.busy() && m.last_attempt().has_value(); });
  ASSERT_TRUE(m.last_attempt());
  EXPECT_EQ(m.last_attempt()->outcome, "interrupted");
  EXPECT_EQ(m.last_attempt()->verdict(), "fail");
  EXPECT_NE(m.state().trials[0].status, session::TrialStatus::kAccepted);
  EXPECT_EQ(m.current_trial(), 0);
  EXPECT_TRUE(fs::file_size(dir / "LMC_Naiv_Static101.raw.txt") > 1000);
  // The operator keeps it anyway: journaled, with a note saying so.
  ASSERT_EQ(m.accept_last(), "");
  EXPECT_EQ(m.state().trials[0].status, session::TrialStatus::kAccepted);
  ASSERT_FALSE(m.state().trials[0].notes.empty());
  EXPECT_NE(m.state().trials[0].notes.back().find("accepted by the operator"), std::string::npos);
  m.close();
  fs::remove_all(dir);
}

TEST(RecordSessionModel, OpeningAnotherProcesssSessionOrABadFolderSaysWhy) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordSessionModel a;
  ASSERT_EQ(a.create(dir, quick(), fast_sim()), "");
  RecordSessionModel b;
  const std::string locked = b.open(dir, fast_sim());
  EXPECT_NE(locked, "");  // the folder's lock is held by `a`
  EXPECT_FALSE(b.has_session());
  EXPECT_NE(b.open(dir / "nothing-here", fast_sim()).find("not a subject session"), std::string::npos);
  RecordSessionModel c;
  EXPECT_NE(c.create(test::fresh_test_dir("record_model_bad"), quick("../escape"), fast_sim()).find("subject id"),
            std::string::npos);
  a.close();
  ASSERT_EQ(b.open(dir, fast_sim()), "");
  EXPECT_TRUE(b.recovered().empty());
  b.close();
  fs::remove_all(dir);
}

TEST(RecordSessionModel, OverrideNeedsAReasonAndIsJournaled) {
  const fs::path dir = test::fresh_test_dir("record_model");
  RecordSessionModel m;
  ASSERT_EQ(m.create(dir, quick(), fast_sim()), "");
  EXPECT_NE(m.override_preflight("  "), "");
  EXPECT_TRUE(m.needs_preflight());
  ASSERT_EQ(m.override_preflight("controllers checked by hand"), "");
  EXPECT_FALSE(m.needs_preflight());
  EXPECT_EQ(m.state().preflight_override.at("Naiv"), "controllers checked by hand");
  m.close();
  fs::remove_all(dir);
}

TEST(RecordSessionModel, ACalibratingProtocolCalibratesTheBlockBeforeItsFirstTrial) {
  const fs::path dir = test::fresh_test_dir("record_model_calibration");
  session::NewSessionSpec spec = quick("S09");
  spec.protocol = "study-calibrated";  // 5 s still hand before each block
  spec.duration_override_s = 1.0;
  RecordSettings settings = fast_sim();
  settings.sim.calibration_random_translation_mm = 20;
  RecordSessionModel m;
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

}  // namespace record_model_test
}  // namespace lmc::ui
