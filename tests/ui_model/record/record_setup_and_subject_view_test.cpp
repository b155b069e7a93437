// The Record tab's set-up form, resume notice, subject screen view and motion pictogram, without
// ImGui: each form field refused by the core rule it mirrors, the spec built like `lmc session
// new`'s, the plain notice of an interrupted session, and what the subject sees at each stage.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/session/session_folder.h"
#include "core/session/trial_files.h"
#include "tests/support/scratch_dir.h"
#include "ui/model/record/motion_pictogram.h"
#include "ui/model/record/record_setup_form.h"
#include "ui/model/record/record_state.h"
#include "ui/model/record/resume_notice.h"
#include "ui/model/record/subject_screen_link.h"
#include "ui/model/record/subject_text_scale.h"
#include "ui/model/record/subject_view.h"
#include "ui/model/record/subject_window_placement.h"

namespace lmc::ui {
namespace record_setup_and_subject_view_test {  // named: test files share unity batches

namespace fs = std::filesystem;

void set(char* field, size_t size, const std::string& text) {
  std::snprintf(field, size, "%s", text.c_str());
}

// An empty quick session of `subject` at `dir` (its lock goes with the folder object).
void make(const fs::path& dir, const std::string& subject) {
  NewSessionSpec spec;
  spec.subject.subject_id = subject;
  spec.protocol = "quick";
  (void)SessionFolder::create(dir, spec);
}

RecordSettings fast_sim() {
  RecordSettings s;
  s.fast = true;
  s.countdown_s = 0;
  return s;
}

TEST(RecordSetupForm, OffersTheShippedProtocolsAndStartsOnTheStudy) {
  const RecordSetupForm f;
  ASSERT_GE(f.protocols.size(), 2U);
  EXPECT_EQ(f.protocol_name(), "study");
  bool quick_listed = false;
  for (const auto& p : f.protocols) {
    if (p.name != "quick") continue;
    quick_listed = true;
    EXPECT_NE(p.label.find("2 trials, 1 layout"), std::string::npos) << p.label;
    EXPECT_NE(p.description.find("demos"), std::string::npos) << p.description;
  }
  EXPECT_TRUE(quick_listed);
  EXPECT_FALSE(check_setup_form(f).any()) << check_setup_form(f).first();
}

TEST(RecordSetupForm, EachFieldIsRefusedByTheRuleTheFolderUses) {
  RecordSetupForm f;
  set(f.subject, sizeof f.subject, "../escape");
  EXPECT_NE(check_setup_form(f).subject.find("subject id"), std::string::npos);
  set(f.subject, sizeof f.subject, "");
  EXPECT_NE(check_setup_form(f).subject, "");
  set(f.subject, sizeof f.subject, "S01");
  f.hand_length_mm = 18.6F;  // centimetres typed
  EXPECT_NE(check_setup_form(f).hand_length.find("between 30 and 400"), std::string::npos);
  f.hand_length_mm = 186;
  f.hand_breadth_mm = -4;
  EXPECT_NE(check_setup_form(f).hand_breadth, "");
  f.hand_breadth_mm = 0;  // not measured
  EXPECT_EQ(check_setup_form(f).hand_breadth, "");
  set(f.vicon, sizeof f.vicon, "10.0.0.2:abc");
  EXPECT_NE(check_setup_form(f).vicon.find("not a UDP port"), std::string::npos);
  set(f.vicon, sizeof f.vicon, "");
  set(f.vicon_database, sizeof f.vicon_database, "D:/Lab/Study");
  EXPECT_NE(check_setup_form(f).vicon_database.find("Vicon target"), std::string::npos);
  EXPECT_THROW((void)f.spec(), std::exception);  // the shared builder refuses it too
  set(f.vicon, sizeof f.vicon, "10.0.0.2:31");
  const fs::path busy = test::fresh_test_dir("setup_form");
  fs::create_directories(busy);
  std::ofstream(busy / "something.txt") << "x";
  set(f.folder, sizeof f.folder, busy.string());
  EXPECT_NE(check_setup_form(f).folder.find("not an empty folder"), std::string::npos);
  EXPECT_EQ(check_setup_form(f).first(), check_setup_form(f).folder);
  set(f.folder, sizeof f.folder, (busy / "new").string());
  EXPECT_FALSE(check_setup_form(f).any()) << check_setup_form(f).first();
  // The spec is the one `lmc session new` builds for the same text.
  const NewSessionSpec spec = f.spec();
  EXPECT_EQ(spec.subject.subject_id, "S01");
  EXPECT_EQ(spec.subject.hand_length_mm.value_or(0), 186);
  EXPECT_FALSE(spec.subject.hand_breadth_mm.has_value());
  EXPECT_EQ(spec.protocol, "study");
  EXPECT_EQ(spec.vicon.at("host"), "10.0.0.2");
  EXPECT_EQ(spec.vicon.at("port"), 31);
  EXPECT_EQ(spec.vicon.at("database_path"), "D:/Lab/Study");
  EXPECT_EQ(f.new_session_dir(), busy / "new");
  fs::remove_all(busy);
}

TEST(RecordSetupForm, ListsSessionsWithTheirProgressNewestFirst) {
  const fs::path root = test::fresh_test_dir("setup_list");
  fs::create_directories(root / "not-a-session");
  {
    NewSessionSpec spec;
    spec.subject.subject_id = "S02";
    spec.protocol = "quick";
    auto a = SessionFolder::create(root / "S02-a", spec);
    a.trial_started(0);
  }  // cut off while recording
  const auto listed = list_sessions(root);
  ASSERT_EQ(listed.size(), 1U);
  EXPECT_EQ(listed[0].subject, "S02");
  EXPECT_EQ(listed[0].protocol, "quick");
  EXPECT_EQ(listed[0].total, 2);
  EXPECT_EQ(listed[0].accepted, 0);
  EXPECT_EQ(listed[0].interrupted, 1);
  EXPECT_TRUE(list_sessions(root / "missing").empty());
  fs::remove_all(root);
}

TEST(RecordSetupForm, ListsSessionsOneFolderDownGroupedByFolder) {
  // sessions/S03, sessions/demo/S01 and S02 (the demo sessions), sessions/demo/notes (not a
  // session) and sessions/old/2024/S04 (two levels down: not looked at).
  const fs::path root = test::fresh_test_dir("setup_list_nested");
  make(root / "S03", "S03");
  make(root / "demo" / "S01", "S01");
  make(root / "demo" / "S02", "S02");
  make(root / "old" / "2024" / "S04", "S04");
  fs::create_directories(root / "demo" / "notes");
  // S01's journal written last: it comes first in its folder.
  const auto now = fs::file_time_type::clock::now();
  fs::last_write_time(root / "demo" / "S02" / kJournalFile, now - std::chrono::hours(2));
  fs::last_write_time(root / "demo" / "S01" / kJournalFile, now - std::chrono::hours(1));
  const auto listed = list_sessions(root);
  ASSERT_EQ(listed.size(), 3U);
  EXPECT_EQ(listed[0].subject, "S03");
  EXPECT_EQ(listed[0].group, "");
  EXPECT_EQ(listed[1].subject, "S01");
  EXPECT_EQ(listed[1].group, "demo");
  EXPECT_EQ(listed[1].dir, root / "demo" / "S01");
  EXPECT_EQ(listed[2].subject, "S02");
  EXPECT_EQ(listed[2].group, "demo");
  EXPECT_EQ(listed[2].total, 2);
  EXPECT_TRUE(listed[2].problem.empty()) << listed[2].problem;
  fs::remove_all(root);
}

// After scripts/run the demo lives in its own folder (LMC_SESSIONS_DIR/demo here), not in the
// user's data folder: the resume list shows it under its full path rather than "No sessions yet",
// and once only when the demo folder is inside the sessions folder.
TEST(RecordSetupForm, TheResumeListShowsTheDemoSessionsToo) {
  const fs::path base = test::fresh_test_dir("setup_resume_demo");
  const fs::path own = base / "data";
  make(own / "P01", "P01");
  make(base / "project" / "demo" / "S01", "S01");
  const char* old = std::getenv("LMC_SESSIONS_DIR");
  const std::string saved = old != nullptr ? old : "";
  ::setenv("LMC_SESSIONS_DIR", (base / "project").c_str(), 1);
  const auto listed = list_resumable_sessions(own);
  const auto inside = list_resumable_sessions(base / "project");
  if (old != nullptr)
    ::setenv("LMC_SESSIONS_DIR", saved.c_str(), 1);
  else
    ::unsetenv("LMC_SESSIONS_DIR");
  ASSERT_EQ(listed.size(), 2U);
  EXPECT_EQ(listed[0].subject, "P01");
  EXPECT_EQ(listed[0].group, "");
  EXPECT_EQ(listed[1].subject, "S01");
  EXPECT_EQ(listed[1].group, (base / "project" / "demo").string());
  ASSERT_EQ(inside.size(), 1U) << "the demo folder inside the sessions folder is listed once";
  EXPECT_EQ(inside[0].group, "demo");
  fs::remove_all(base);
}

// A subject id is a person: the sessions already recorded for the form's id, wherever they sit
// under the sessions folder (the demo's S01 one folder down too), are found before a new one is made.
TEST(RecordSetupForm, FindsTheSessionsAlreadyRecordedForASubjectId) {
  const fs::path root = test::fresh_test_dir("setup_same_subject");
  make(root / "P01-first", "P01");
  make(root / "P02", "P02");
  make(root / "demo" / "S01", "S01");
  const auto listed = list_sessions(root);
  const auto p01 = sessions_of_subject(listed, "P01");
  ASSERT_EQ(p01.size(), 1U);
  EXPECT_EQ(p01[0].dir, root / "P01-first");
  ASSERT_EQ(sessions_of_subject(listed, "S01").size(), 1U);
  EXPECT_TRUE(sessions_of_subject(listed, "P03").empty());
  EXPECT_TRUE(sessions_of_subject(listed, "p01").empty()) << "ids are compared exactly, as the export does";
  const std::string text = subject_clash_text("P01", p01);
  EXPECT_NE(text.find("Subject P01 already has 1 session:"), std::string::npos) << text;
  EXPECT_NE(text.find((root / "P01-first").string() + " (0 of 2 trials accepted)"), std::string::npos) << text;
  fs::remove_all(root);
}

TEST(RecordResumeNotice, AnInterruptedSessionSaysWhatHappenedAndWhereItContinues) {
  const fs::path dir = test::fresh_test_dir("resume_notice");
  {
    NewSessionSpec spec;
    spec.subject.subject_id = "S03";
    spec.protocol = "quick";
    auto f = SessionFolder::create(dir, spec);
    f.trial_started(0);
    std::ofstream(lmc::trial_files(dir, "Naiv_Static101").recording) << "partial\n";
  }  // the process "dies" mid-trial
  RecordState m;
  ASSERT_EQ(m.open(dir, fast_sim()), "");
  const auto& notice = m.resume_notice();
  ASSERT_EQ(notice.size(), 2U);
  EXPECT_NE(notice[0].find("Naiv_Static101 was cut off while recording"), std::string::npos) << notice[0];
  EXPECT_NE(notice[0].find("superseded/Naiv_Static101.attempt1/"), std::string::npos) << notice[0];
  EXPECT_NE(notice[1].find("0 of 2 trials accepted"), std::string::npos) << notice[1];
  EXPECT_NE(notice[1].find("continues with trial 1 of 2, Naiv_Static101 (layout Naiv)"), std::string::npos)
      << notice[1];
  m.close();
  // A session opened again with nothing cut off still says where it continues; a new one says nothing.
  ASSERT_EQ(m.open(dir, fast_sim()), "");
  ASSERT_EQ(m.resume_notice().size(), 1U);
  m.close();
  RecordState fresh;
  NewSessionSpec spec;
  spec.subject.subject_id = "S04";
  spec.protocol = "quick";
  ASSERT_EQ(fresh.create(test::fresh_test_dir("resume_notice_new"), spec, fast_sim()), "");
  EXPECT_TRUE(fresh.resume_notice().empty());
  const fs::path fresh_dir = fresh.dir();
  fresh.close();
  fs::remove_all(fresh_dir);
  fs::remove_all(dir);
}

TEST(RecordResumeNotice, ACompleteSessionSaysNothingIsLeft) {
  SessionState st;
  EXPECT_NE(resume_notice(st, {}).back().find("nothing is left to record"), std::string::npos);
}

TEST(MotionPictogram, AnimatesBetweenTheTrialMotionsStartAndEnd) {
  EXPECT_DOUBLE_EQ(pictogram_progress(0.0), 0.0);     // holds the start
  EXPECT_DOUBLE_EQ(pictogram_progress(1.6), 1.0);     // holds the end
  EXPECT_NEAR(pictogram_progress(1.125), 0.5, 1e-9);  // half-way out
  EXPECT_NEAR(pictogram_progress(2.625), 0.5, 1e-9);  // half-way back
  EXPECT_DOUBLE_EQ(pictogram_progress(3.0), 0.0);     // one cycle
  const auto p = motion_pictogram("horizontal/index", 1.125);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->motion, HandMotion::kIndexFlexion);
  EXPECT_EQ(p->orientation, HandOrientation::kHorizontal);
  const int tip = digit_point(Digit::kIndex, Joint::kEnd);
  const double travel = (p->end.point(tip) - p->start.point(tip)).norm();
  EXPECT_GT(travel, 50.0);
  EXPECT_GT((p->now.point(tip) - p->start.point(tip)).norm(), 0.2 * travel);
  EXPECT_GT((p->now.point(tip) - p->end.point(tip)).norm(), 0.2 * travel);
  const auto still = motion_pictogram("vertical/static", 1.125);
  ASSERT_TRUE(still);
  EXPECT_EQ(still->orientation, HandOrientation::kVertical);
  EXPECT_NEAR((still->end.point(tip) - still->start.point(tip)).norm(), 0.0, 1e-9);
  EXPECT_FALSE(motion_pictogram("juggling", 0.0));
  // The subject's own hand size when it was measured.
  const auto big = motion_pictogram("horizontal/index", 0.0, 230, 100);
  ASSERT_TRUE(big);
  EXPECT_GT((big->start.point(tip) - big->start.point(kPalm)).norm(),
            (p->start.point(tip) - p->start.point(kPalm)).norm());
}

TrialType index_type() {
  TrialType t;
  t.key = "Index";
  t.sim_motion = "index";
  t.duration_s = 3;
  t.subject_cue = "Bend your index finger";
  return t;
}

// Every stage the subject can see has words for the subject (no "operator", no session folder),
// and the operator's countdown is the subject's number: one rule for both screens.
TEST(SubjectView, EveryStageHasSubjectFacingWordsAndOneCountdown) {
  const TrialType type = index_type();
  SubjectViewInputs in;
  SubjectView v = build_subject_view(in, 0);
  EXPECT_EQ(v.stage, SubjectStage::kNoSession);
  EXPECT_EQ(v.headline, "Welcome");
  EXPECT_EQ(v.cue.find("operator"), std::string::npos) << v.cue;
  EXPECT_FALSE(v.cue.empty());
  in.has_session = true;
  in.type = &type;
  for (const auto phase :
       {devices::TrialPhase::kWaitingForStreams, devices::TrialPhase::kWaitingForVicon, devices::TrialPhase::kCountdown,
        devices::TrialPhase::kRecording, devices::TrialPhase::kFinishing, devices::TrialPhase::kDone}) {
    in.phase = phase;
    v = build_subject_view(in, 0);
    EXPECT_FALSE(v.headline.empty()) << devices::trial_phase_name(phase);
    EXPECT_FALSE(v.cue.empty()) << devices::trial_phase_name(phase);
    EXPECT_EQ(v.headline.find("operator"), std::string::npos) << v.headline;
  }
  // The operator's "starts in N s" and the subject's N, at the same remaining time.
  for (const double remaining : {2.999, 2.3, 2.0, 1.5, 1.0, 0.4, 0.0}) {
    in.phase = devices::TrialPhase::kCountdown;
    in.countdown_remaining_s = remaining;
    EXPECT_EQ(build_subject_view(in, 0).headline, std::to_string(countdown_number(remaining))) << remaining;
  }
  EXPECT_EQ(countdown_number(2.3), 3);
  EXPECT_EQ(countdown_number(0.0), 1);
  EXPECT_EQ(seconds_left(4.0, 0.6), 4);
  EXPECT_EQ(seconds_left(4.0, 5.0), 0);
}

TEST(SubjectView, ShowsTheRedCircleOnlyWhileRecordingAndNothingForTheOperator) {
  const TrialType type = index_type();
  ProtocolPose pose;
  pose.key = "horizontal";
  pose.cue = "palm facing down";
  SubjectViewInputs in;
  EXPECT_EQ(build_subject_view(in, 0).stage, SubjectStage::kNoSession);
  in.has_session = true;
  in.type = &type;
  in.pose = &pose;
  in.sim_motion = "horizontal/index";
  SubjectView v = build_subject_view(in, 0);
  EXPECT_EQ(v.stage, SubjectStage::kGetReady);
  EXPECT_FALSE(v.red_circle);
  EXPECT_EQ(v.cue, "Bend your index finger");
  EXPECT_EQ(v.pose_cue, "palm facing down");
  ASSERT_TRUE(v.pictogram);
  EXPECT_EQ(v.pictogram->motion, HandMotion::kIndexFlexion);

  in.phase = devices::TrialPhase::kWaitingForStreams;
  v = build_subject_view(in, 0);
  EXPECT_EQ(v.stage, SubjectStage::kWaiting);
  EXPECT_FALSE(v.red_circle);

  in.phase = devices::TrialPhase::kCountdown;
  in.countdown_remaining_s = 2.3;
  v = build_subject_view(in, 0);
  EXPECT_EQ(v.stage, SubjectStage::kCountdown);
  EXPECT_EQ(v.headline, "3");
  EXPECT_FALSE(v.red_circle);
  in.countdown_remaining_s = 0.01;
  EXPECT_EQ(build_subject_view(in, 0).headline, "1");  // never "0" before recording

  in.phase = devices::TrialPhase::kRecording;
  in.recording_s = 0.6;
  v = build_subject_view(in, 0);
  EXPECT_EQ(v.stage, SubjectStage::kRecording);
  EXPECT_TRUE(v.red_circle);
  EXPECT_EQ(v.time_text, "3 s left");
  in.recording_s = 2.2;
  EXPECT_EQ(build_subject_view(in, 0).time_text, "1 s left");

  in.phase.reset();
  in.finished = true;
  v = build_subject_view(in, 0);
  EXPECT_EQ(v.stage, SubjectStage::kDone);
  EXPECT_FALSE(v.red_circle);
  EXPECT_FALSE(v.pictogram);
}

TEST(SubjectView, FollowsTheRecordModelsSession) {
  const fs::path dir = test::fresh_test_dir("subject_view");
  RecordState m;
  EXPECT_EQ(build_subject_view(subject_view_inputs(m), 0).stage, SubjectStage::kNoSession);
  NewSessionSpec spec;
  spec.subject.subject_id = "S05";
  spec.protocol = "quick";
  ASSERT_EQ(m.create(dir, spec, fast_sim()), "");
  const SubjectView v = build_subject_view(subject_view_inputs(m), 0);
  EXPECT_EQ(v.stage, SubjectStage::kGetReady);
  EXPECT_EQ(v.cue, m.trial_type(0).subject_cue);
  EXPECT_EQ(v.pose_cue, "palm facing down");
  ASSERT_TRUE(v.pictogram);
  EXPECT_EQ(v.pictogram->motion, HandMotion::kOpen);  // the quick protocol starts static
  m.select(1);
  EXPECT_EQ(build_subject_view(subject_view_inputs(m), 0).pictogram->motion, HandMotion::kIndexFlexion);
  m.close();
  fs::remove_all(dir);
}

TEST(SubjectScreenArg, MonitorNumberWindowOrNothing) {
  std::string error;
  auto r = parse_subject_screen_arg("", error);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->monitor, -1);
  EXPECT_FALSE(r->windowed);
  r = parse_subject_screen_arg("1", error);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->monitor, 1);
  r = parse_subject_screen_arg("window", error);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->windowed);
  EXPECT_FALSE(parse_subject_screen_arg("left", error));
  EXPECT_NE(error.find("'left'"), std::string::npos);
}

TEST(SubjectScreenPlacement, OneMonitorOpensWindowedUnlessTheOperatorChose) {
  SubjectScreenLink link;
  link.monitors = {"eDP-1 (1920x1080, primary)"};
  // F2 on a one-monitor bench: a window, not a cover over the operator's own window.
  EXPECT_TRUE(subject_screen_windowed(link));
  link.monitors.push_back("HDMI-1 (1920x1080)");
  EXPECT_FALSE(subject_screen_windowed(link));  // two monitors: the second is covered
  link.monitors.clear();
  EXPECT_TRUE(subject_screen_windowed(link));  // none seen yet: nothing to cover safely
  // Full screen only on a second monitor: with one, a window even when the operator unticked it
  // (covering the only monitor hid Start and the note field).
  link.monitors = {"eDP-1 (1920x1080, primary)"};
  link.windowed = false;
  EXPECT_TRUE(subject_screen_windowed(link));
  // With two the operator's choice wins either way.
  link.monitors.push_back("HDMI-1 (1920x1080)");
  EXPECT_FALSE(subject_screen_windowed(link));
  link.windowed = true;
  EXPECT_TRUE(subject_screen_windowed(link));
}

// One monitor: the window opens beside the workbench when there is room, else in the corner over
// the 3D view, never over the operator's controls; where the operator left it wins when it is
// still on a monitor.
TEST(SubjectScreenPlacement, TheWindowOpensBesideTheWorkbenchOrWhereTheOperatorLeftIt) {
  const std::vector<ScreenRect> laptop = {{0, 0, 1920, 1080}};
  // The workbench at 1280 × 800 at the left: the window fills the strip to its right.
  const ScreenRect beside = subject_window_rect(laptop, -1, {0, 0, 1280, 800}, std::nullopt);
  EXPECT_GE(beside.x, 1280);
  EXPECT_LE(beside.x + beside.width, 1920);
  EXPECT_GE(beside.width, 400);
  EXPECT_EQ(beside.height, beside.width * 10 / 16);
  // Maximised: a third of the monitor, bottom right, above a taskbar; the left two thirds (the
  // trial list, Start, the verdict and the note line) stay clear.
  const ScreenRect corner = subject_window_rect(laptop, -1, {0, 0, 1920, 1080}, std::nullopt);
  EXPECT_EQ(corner.width, 640);
  EXPECT_EQ(corner.height, 400);
  EXPECT_EQ(corner.x + corner.width, 1920 - 8);
  EXPECT_LE(corner.y + corner.height, 1080 - 48);
  EXPECT_GE(corner.x, 1920 * 2 / 3 - 8);
  // Never the old 1024 × 640 at (40, 40) over the controls.
  EXPECT_NE(corner, (ScreenRect{40, 40, 1024, 640}));
  // Remembered and still on a monitor: there; off every monitor now (a projector unplugged): ignored.
  const ScreenRect left_there{100, 500, 700, 440};
  EXPECT_EQ(subject_window_rect(laptop, -1, {0, 0, 1920, 1080}, left_there), left_there);
  EXPECT_EQ(subject_window_rect(laptop, -1, {0, 0, 1920, 1080}, ScreenRect{2500, 100, 700, 440}), corner);
  // The remembered line round-trips; a damaged one is ignored.
  EXPECT_EQ(parse_subject_window_rect(subject_window_rect_text(left_there)), left_there);
  EXPECT_FALSE(parse_subject_window_rect("100 500 wide").has_value());
  EXPECT_FALSE(parse_subject_window_rect("1 2 3 4 5").has_value());
  EXPECT_FALSE(parse_subject_window_rect("1 2 -3 4").has_value());
}

TEST(SubjectScreenPlacement, TheCommandLineChoosesOnlyWhatItNames) {
  SubjectScreenLink link;
  link.monitors = {"eDP-1 (1920x1080, primary)"};
  std::string error;
  apply_subject_screen_request(link, *parse_subject_screen_arg("", error));
  EXPECT_TRUE(link.open);
  EXPECT_FALSE(link.windowed.has_value());
  EXPECT_TRUE(subject_screen_windowed(link));  // the bench decides: one monitor, a window
  apply_subject_screen_request(link, *parse_subject_screen_arg("0", error));
  EXPECT_EQ(link.monitor, 0);
  // Asked to cover monitor 0: with one monitor it stays a window (covering it would hide the
  // operator's); with a second one it covers the one asked for.
  EXPECT_TRUE(subject_screen_windowed(link));
  link.monitors.push_back("HDMI-1 (1920x1080)");
  EXPECT_FALSE(subject_screen_windowed(link));
  apply_subject_screen_request(link, *parse_subject_screen_arg("window", error));
  EXPECT_TRUE(subject_screen_windowed(link));
}

TEST(SubjectTextScale, FollowsTheWindowBelowTheDesignSize) {
  EXPECT_FLOAT_EQ(subject_text_scale(1920, 1080), 1.0F);  // never larger than the fonts are made
  EXPECT_FLOAT_EQ(subject_text_scale(1280, 800), 1.0F);
  EXPECT_FLOAT_EQ(subject_text_scale(1024, 640), 0.8F);  // the one-monitor window
  EXPECT_FLOAT_EQ(subject_text_scale(1280, 400), 0.5F);  // the tighter direction decides
  EXPECT_FLOAT_EQ(subject_text_scale(100, 100), kSubjectMinTextScale);
}

TEST(SubjectTextScale, ShrinksUntilTheTextFits) {
  // Text whose height goes with the square of the scale (it wraps into more lines as it grows):
  // 400 px at scale 1.
  const auto height_at = [](float s) { return 400.0F * s * s; };
  EXPECT_FLOAT_EQ(fit_subject_text_scale(1.0F, 500.0F, height_at), 1.0F);  // fits already
  const float s = fit_subject_text_scale(0.8F, 200.0F, height_at);
  EXPECT_LE(height_at(s), 200.0F);
  EXPECT_GT(s / 0.9F, 0.70710678F);  // the largest 10 % step that fits, not smaller
  EXPECT_NEAR(s, 0.8F * 0.9F * 0.9F, 1e-6);
  // Nothing fits: the smallest readable scale, not zero.
  EXPECT_FLOAT_EQ(fit_subject_text_scale(1.0F, 1.0F, height_at), kSubjectMinTextScale);
}

}  // namespace record_setup_and_subject_view_test
}  // namespace lmc::ui
