// The Record tab's model, the parts behind Esc, N and the live fused hand: a trial
// recorded in real time on the simulated rig shows a fused hand from the live fusion worker with
// measured latency; Esc aborts it (kept, journaled as aborted, verdict fail, redone next; in the
// countdown, an attempt without frames that cannot be kept); a failed attempt is kept only after a
// question whose default is No; N
// notes are journaled at once between trials and after the trial when typed during one.
// Waits poll with a generous deadline, never a fixed sleep.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/io/layout_json.h"
#include "core/session/session_folder.h"
#include "tests/support/scratch_dir.h"
#include "ui/model/devices/fusion_readout.h"
#include "ui/model/record/record_state.h"
#include "ui/model/workbench_context.h"

namespace lmc::ui {
namespace record_abort_note_live_test {  // named: test files share unity batches

namespace fs = std::filesystem;

RecordSettings real_time_sim() {
  RecordSettings s;
  s.backend = "sim";
  s.fast = false;
  s.countdown_s = 0;
  return s;
}

NewSessionSpec quick() {
  NewSessionSpec spec;
  spec.subject.subject_id = "S07";
  spec.protocol = "quick";
  return spec;
}

// Polls until `done` or the deadline; returns the status lines poll() gave.
std::vector<StatusReport> poll_until(RecordState& m, const std::function<bool()>& done, double timeout_s = 60) {
  std::vector<StatusReport> lines;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (StatusReport line = m.poll(); !line.empty()) lines.push_back(std::move(line));
    if (done()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return lines;
}

TEST(RecordLiveFusion, ARealTimeTrialShowsTheFusedHandAndItsLatencyThenEscAbortsItKeptAndRedoable) {
  const fs::path dir = test::fresh_test_dir("record_live");
  RecordState m;
  ASSERT_EQ(m.create(dir, quick(), real_time_sim()), "");
  ASSERT_EQ(m.override_preflight("test"), "");
  EXPECT_NE(m.abort_trial(), "");  // nothing records yet
  EXPECT_EQ(fusion_latency_line(m.fusion_stats()), "fusion: waiting for frames");
  ASSERT_EQ(m.start_trial(), "");

  // The fused hand comes from the worker fed with every frame, with its latency measured.
  poll_until(m, [&] { return m.live_fused() && m.live_fused()->has_hand && m.fusion_stats().window_frames > 40; });
  ASSERT_TRUE(m.live_fused());
  EXPECT_TRUE(m.live_fused()->has_hand);
  const devices::LiveFusionStats stats = m.fusion_stats();
  EXPECT_GT(stats.frames_fused, 40);
  EXPECT_TRUE(std::isfinite(stats.latency_max_ms));
  EXPECT_LE(stats.latency_p50_ms, stats.latency_p95_ms);
  EXPECT_LE(stats.latency_p95_ms, stats.latency_max_ms);
  EXPECT_NE(fusion_latency_line(stats).find("p95"), std::string::npos);
  // Notes typed while the trial records wait for it.
  EXPECT_NE(m.add_note("   "), "");
  ASSERT_EQ(m.add_note("  subject coughed at 1 s "), "");

  // Esc. The status line is an error because the verdict is fail, as the model says (the tab
  // used to guess it from the line's words).
  ASSERT_EQ(m.abort_trial(), "");
  const auto reports = poll_until(m, [&] { return !m.busy() && m.last_attempt().has_value(); });
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].severity, Severity::kError) << reports[0].text;
  EXPECT_EQ(reports[0].text.rfind("Naiv_Static101: fail", 0), 0U) << reports[0].text;
  ASSERT_TRUE(m.last_attempt());
  EXPECT_EQ(m.last_attempt()->outcome, "aborted");
  EXPECT_EQ(m.last_attempt()->reason, "aborted by the operator");
  EXPECT_EQ(m.last_attempt()->verdict(), "fail");
  EXPECT_FALSE(m.live_fused());                                           // the live view ends with the trial
  EXPECT_TRUE(fs::file_size(dir / "LMC_Naiv_Static101.raw.txt") > 1000);  // its rows are kept

  // The journal says so, as `lmc session status` reads it.
  const auto on_disk = read_session_state(dir);
  ASSERT_EQ(on_disk.trials[0].attempts.size(), 1U);
  EXPECT_EQ(on_disk.trials[0].attempts[0].outcome, "aborted");
  EXPECT_EQ(on_disk.trials[0].attempts[0].reason, "aborted by the operator");
  EXPECT_EQ(on_disk.trials[0].status, TrialStatus::kFailed);
  ASSERT_EQ(on_disk.trials[0].notes.size(), 1U);
  EXPECT_EQ(on_disk.trials[0].notes[0], "subject coughed at 1 s");

  // A note between trials is journaled at once, on the last trial recorded.
  EXPECT_EQ(m.note_trial(), 0);
  ASSERT_EQ(m.add_note("cable moved"), "");
  ASSERT_EQ(m.state().trials[0].notes.size(), 2U);
  EXPECT_EQ(m.state().trials[0].notes[1], "cable moved");

  // Redo: the aborted attempt goes under superseded/ and the trial records again.
  ASSERT_EQ(m.redo(), "");
  EXPECT_EQ(m.current_trial(), 0);
  ASSERT_FALSE(m.state().trials[0].attempts.at(0).superseded_dir.empty());
  EXPECT_TRUE(fs::exists(dir / m.state().trials[0].attempts[0].superseded_dir / "LMC_Naiv_Static101.raw.txt"));
  ASSERT_EQ(m.start_trial(), "");
  poll_until(m, [&] { return m.live() && m.live()->recorder.frames_written > 20; });
  m.stop_trial();  // Space: interrupted, not aborted
  poll_until(m, [&] { return !m.busy() && m.last_attempt() && m.last_attempt()->attempt == 2; });
  ASSERT_TRUE(m.last_attempt());
  EXPECT_EQ(m.last_attempt()->outcome, "interrupted");
  m.close();
  fs::remove_all(dir);
}

// One hub for real controllers: a session set to share the workbench's live rig records through
// the rig's running hub (started for it when needed) instead of opening the backend again, the
// rig refuses to be stopped or to record meanwhile, and gets its hub back on close. Shown with the
// simulated rig, which goes through the same path as LeapC here.
TEST(RecordLiveFusion, ASharedRigSessionRecordsThroughTheWorkbenchsHubAndGivesItBack) {
  const fs::path dir = test::fresh_test_dir("record_shared");
  WorkbenchContext context;
  context.layout().publish(load_layout_or_preset("paper-initial"));  // as the Layout tab would
  LiveRig& rig = context.rig();
  RecordState m(&rig);
  RecordSettings settings = real_time_sim();
  settings.share_rig_hub = true;
  ASSERT_EQ(m.create(dir, quick(), settings), "");
  ASSERT_TRUE(rig.running());  // started for the session
  EXPECT_TRUE(rig.lent());
  const devices::DeviceHub* hub = rig.hub();
  EXPECT_NE(rig.start("sim"), "");  // refused while lent
  EXPECT_NE(rig.start_trial(dir / "devices-test", "t", 1.0), "");
  rig.stop();
  EXPECT_TRUE(rig.running());
  EXPECT_EQ(rig.hub(), hub);

  ASSERT_EQ(m.start_preflight(), "");
  poll_until(m, [&] { return !m.busy() && m.last_preflight().has_value(); });
  ASSERT_TRUE(m.last_preflight());
  ASSERT_TRUE(m.last_preflight()->ok()) << m.last_preflight()->failures().front();
  ASSERT_EQ(m.start_trial(), "");
  poll_until(m, [&] { return !m.busy() && m.last_attempt().has_value(); });
  ASSERT_TRUE(m.last_attempt());
  EXPECT_EQ(m.last_attempt()->outcome, "completed");
  EXPECT_NE(m.last_attempt()->verdict(), "fail");
  // The rig kept running the whole time (the engine leaves a hub it did not start running), and
  // its own fusion saw the same frames the session recorded.
  EXPECT_TRUE(rig.running());
  EXPECT_EQ(rig.hub(), hub);
  ASSERT_NE(rig.fusion(), nullptr);
  EXPECT_GT(rig.fusion()->stats().frames_fused, 0);
  m.close();
  EXPECT_FALSE(rig.lent());
  rig.stop();  // the Devices tab's Stop works again
  EXPECT_FALSE(rig.running());
  fs::remove_all(dir);
}

// Keeping a failed trial is a decision, not a keystroke: Esc in the countdown gives an attempt
// without a frame whose verdict says so (not a controller fault) and which cannot be kept at all;
// an attempt with frames that failed is kept only after a question naming what failed, whose
// default answer is No.
void start_first_trial(RecordState& m, const fs::path& dir, double countdown_s) {
  RecordSettings settings = real_time_sim();
  settings.countdown_s = countdown_s;
  ASSERT_EQ(m.create(dir, quick(), settings), "");
  ASSERT_EQ(m.override_preflight("test"), "");
  ASSERT_EQ(m.start_trial(), "");
}

TEST(RecordAcceptDecision, EscInTheCountdownIsNoDataNotAControllerFaultAndCannotBeKept) {
  const fs::path dir = test::fresh_test_dir("record_accept_countdown");
  RecordState m;
  start_first_trial(m, dir, 5.0);
  poll_until(m, [&] { return m.live() && m.live()->phase == devices::TrialPhase::kCountdown; });
  ASSERT_TRUE(m.live());
  ASSERT_EQ(m.live()->phase, devices::TrialPhase::kCountdown);
  ASSERT_EQ(m.abort_trial(), "");  // Esc
  poll_until(m, [&] { return !m.busy() && m.last_attempt().has_value(); });
  ASSERT_TRUE(m.last_attempt());
  const auto& a = *m.last_attempt();
  EXPECT_EQ(a.outcome, "aborted");
  EXPECT_EQ(a.frames, 0);
  EXPECT_FALSE(a.reached_go);
  EXPECT_EQ(a.verdict(), "fail");
  ASSERT_TRUE(a.quality);
  ASSERT_EQ(a.quality->reasons.size(), 1U) << "one reason, and no controller blamed";
  EXPECT_EQ(a.quality->reasons[0], "aborted before go — no data");

  // Enter: nothing to ask about, the refusal names what failed; keeping it directly is refused too.
  const std::string why = m.ask_accept();
  EXPECT_NE(why.find("0 frames: aborted before go — no data"), std::string::npos) << why;
  EXPECT_TRUE(m.accept_question().empty());
  EXPECT_NE(m.accept_last(), "");
  EXPECT_NE(m.answer_accept(true), "");
  EXPECT_NE(m.state().trials[0].status, TrialStatus::kAccepted);
  const auto on_disk = read_session_state(dir);
  EXPECT_NE(on_disk.trials[0].status, TrialStatus::kAccepted);
  for (const auto& n : on_disk.trials[0].notes) EXPECT_EQ(n.find("accepted by the operator"), std::string::npos);
  m.close();
  fs::remove_all(dir);
}

TEST(RecordAcceptDecision, AFailedAttemptWithFramesIsKeptOnlyAfterAQuestionWhoseDefaultIsNo) {
  const fs::path dir = test::fresh_test_dir("record_accept_question");
  RecordState m;
  start_first_trial(m, dir, 0.0);
  poll_until(m, [&] { return m.live() && m.live()->recorder.frames_written > 20; });
  m.stop_trial();  // Space mid-trial: interrupted, a fail with frames
  poll_until(m, [&] { return !m.busy() && m.last_attempt().has_value(); });
  ASSERT_TRUE(m.last_attempt());
  EXPECT_EQ(m.last_attempt()->verdict(), "fail");
  EXPECT_GT(m.last_attempt()->frames, 20);
  EXPECT_TRUE(m.last_attempt()->reached_go);

  // Enter asks, naming the frames and the first reason; Enter again (No) keeps nothing.
  ASSERT_EQ(m.ask_accept(), "");
  const std::string q = m.accept_question();
  EXPECT_NE(q.find("Naiv_Static101 failed ("), std::string::npos) << q;
  ASSERT_TRUE(m.last_attempt()->quality);
  EXPECT_NE(q.find(std::to_string(m.last_attempt()->frames) + " frames: " + m.last_attempt()->quality->reasons.front()),
            std::string::npos)
      << q;
  EXPECT_NE(q.find("Keep it anyway?"), std::string::npos) << q;
  EXPECT_EQ(m.state().trials[0].status, TrialStatus::kFailed) << "asking keeps nothing";
  ASSERT_EQ(m.answer_accept(false), "");
  EXPECT_TRUE(m.accept_question().empty());
  EXPECT_EQ(m.state().trials[0].status, TrialStatus::kFailed);
  EXPECT_NE(m.answer_accept(true), "") << "no question is open any more";
  EXPECT_EQ(m.state().trials[0].status, TrialStatus::kFailed);

  // Asked again and answered yes: kept, journaled with the verdict.
  ASSERT_EQ(m.ask_accept(), "");
  ASSERT_EQ(m.answer_accept(true), "");
  EXPECT_EQ(m.state().trials[0].status, TrialStatus::kAccepted);
  ASSERT_FALSE(m.state().trials[0].notes.empty());
  EXPECT_NE(m.state().trials[0].notes.back().find("accepted by the operator despite its verdict (fail)"),
            std::string::npos);
  m.close();
  fs::remove_all(dir);
}

}  // namespace record_abort_note_live_test
}  // namespace lmc::ui
