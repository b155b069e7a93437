// Headless tests of the Record tab's panels, one or more per panel: each is drawn with a real
// session model (a quick session on the simulated rig in a scratch folder) or the real subject
// screen link, and clicks go through ImGuiIO to the panel, which is drawn without a renderer.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "tests/support/scratch_dir.h"
#include "tests/ui/headless_imgui.h"
#include "ui/model/record/record_setup_form.h"
#include "ui/model/record/record_state.h"
#include "ui/model/record/subject_screen_link.h"
#include "ui/model/record/subject_view.h"
#include "ui/tabs/record/record_calibration_panel.h"
#include "ui/tabs/record/record_device_strips_panel.h"
#include "ui/tabs/record/record_note_panel.h"
#include "ui/tabs/record/record_setup_panel.h"
#include "ui/tabs/record/record_trial_list_panel.h"
#include "ui/tabs/record/record_trial_panel.h"
#include "ui/tabs/record/record_verdict_panel.h"
#include "ui/tabs/record/subject_screen_controls_panel.h"
#include "ui/tabs/record/subject_screen_panel.h"

namespace lmc::ui {
namespace record_panels_test {  // named: test files share unity batches

namespace fs = std::filesystem;
using testing::HeadlessImGui;

RecordSettings sim_settings(bool fast) {
  RecordSettings settings;
  settings.fast = fast;
  settings.countdown_s = 0;
  return settings;
}

NewSessionSpec spec_for(const std::string& subject, const std::string& protocol = "quick") {
  NewSessionSpec spec;
  spec.subject.subject_id = subject;
  spec.protocol = protocol;
  return spec;
}

// Polls the model (as the tab does once a frame) until `done`, for at most a minute.
void poll_until(RecordState& model, const std::function<bool()>& done) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!done() && std::chrono::steady_clock::now() < deadline) {
    model.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

// Records the current trial to its verdict.
void record_one_trial(RecordState& model) {
  ASSERT_EQ(model.start_trial(), "");
  poll_until(model, [&] { return model.last_attempt() && !model.busy(); });
  ASSERT_TRUE(model.last_attempt());
}

// A session in a fresh scratch folder, closed and removed at the end of the test.
struct ScratchSession {
  explicit ScratchSession(const std::string& name) : dir(test::fresh_test_dir(name)) {}
  ~ScratchSession() {
    model->close();
    fs::remove_all(dir);
  }
  fs::path dir;
  std::shared_ptr<RecordState> model = std::make_shared<RecordState>();
};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// ---- set-up form ---------------------------------------------------------------------------------

TEST(RecordSetupPanel, CreateStaysDisabledUntilTheSubjectIdIsSafe) {
  HeadlessImGui gui;
  RecordSetupForm form;
  std::snprintf(form.subject, sizeof form.subject, "%s", "S 01/x");
  RecordSetupPanel panel(form);
  SetupAction action = SetupAction::kNone;
  const auto body = [&] {
    const SetupAction a = panel.draw({}, "");
    if (a != SetupAction::kNone) action = a;
  };
  gui.frame(body);
  ASSERT_TRUE(panel.anchors().centre("create"));
  const ImVec2 create = *panel.anchors().centre("create");
  gui.click(create.x, create.y, body);
  EXPECT_EQ(action, SetupAction::kNone);  // refused: the form says why under the field
  std::snprintf(form.subject, sizeof form.subject, "%s", "S01");
  gui.frame(body);
  const ImVec2 create_now = *panel.anchors().centre("create");
  gui.click(create_now.x, create_now.y, body);
  EXPECT_EQ(action, SetupAction::kCreate);
}

// ---- trial list ----------------------------------------------------------------------------------

TEST(RecordTrialListPanel, ListsEveryTrialAndAClickSelectsIt) {
  ScratchSession s("record_panels_list");
  ASSERT_EQ(s.model->create(s.dir, spec_for("S03"), sim_settings(true)), "");
  ASSERT_GE(s.model->state().trials.size(), 2u);
  HeadlessImGui gui;
  RecordTrialListPanel panel(s.model);
  const auto body = [&] { panel.draw(); };
  const std::string text = gui.frame_text(body);
  for (const auto& t : s.model->state().trials)
    EXPECT_TRUE(contains(text, t.plan.name)) << t.plan.name << " in\n" << text;
  EXPECT_TRUE(contains(text, "Layout " + s.model->state().trials[0].plan.layout_key));
  EXPECT_EQ(s.model->current_trial(), 0);
  const auto second = panel.anchors().centre("trial.1");
  ASSERT_TRUE(second);
  gui.click(second->x, second->y, body);
  EXPECT_EQ(s.model->current_trial(), 1) << "the click selected the second trial for the next Start";
}

// ---- trial panel ---------------------------------------------------------------------------------

TEST(RecordTrialPanel, StartIsEnabledOnlyAfterThePreflightOrAnOverrideWithAReason) {
  ScratchSession s("record_panels");
  ASSERT_EQ(s.model->create(s.dir, spec_for("S01"), sim_settings(true)), "");
  HeadlessImGui gui;
  RecordTrialPanel panel(s.model);
  TrialPanelAction action = TrialPanelAction::kNone;
  const auto body = [&] {
    const TrialPanelAction a = panel.draw();
    if (a != TrialPanelAction::kNone) action = a;
  };
  gui.frame(body);
  // Before the pre-flight Space has one meaning and one button: Run pre-flight. No Start is drawn.
  EXPECT_FALSE(panel.anchors().centre("start"));
  ASSERT_TRUE(panel.anchors().centre("preflight"));
  EXPECT_NE(s.model->override_preflight(""), "");  // no reason, no override
  EXPECT_TRUE(s.model->needs_preflight());
  ASSERT_EQ(s.model->override_preflight("controllers checked by hand"), "");
  gui.frame(body);
  ASSERT_TRUE(panel.anchors().centre("start"));
  EXPECT_FALSE(panel.anchors().centre("preflight"));
  const ImVec2 start = *panel.anchors().centre("start");
  gui.click(start.x, start.y, body);
  EXPECT_EQ(action, TrialPanelAction::kStart);
  EXPECT_EQ(s.model->start_trial(), "");  // and the model agrees
}

TEST(RecordTrialPanel, AfterCloseAndReopenNothingOfTheLastVerdictIsDrawnAgainstAnEmptyList) {
  ScratchSession s("record_panels_close");
  RecordState& model = *s.model;
  ASSERT_EQ(model.create(s.dir, spec_for("S02"), sim_settings(true)), "");
  ASSERT_EQ(model.override_preflight("checked by hand"), "");
  record_one_trial(model);
  HeadlessImGui gui;
  RecordTrialPanel panel(s.model);
  RecordNotePanel note(s.model);
  RecordVerdictPanel verdict(s.model, note);
  model.close();
  // The Record tab drew the verdict in the frame of Close: the attempt's trial index into a
  // closed session's (empty) trial list threw std::out_of_range and ended the program.
  EXPECT_NO_THROW(gui.frame([&] { EXPECT_EQ(verdict.draw(), VerdictAction::kNone); }));
  ASSERT_EQ(model.open(s.dir, sim_settings(true)), "");
  EXPECT_NO_THROW(gui.frame([&] { panel.draw(); }));
  EXPECT_NO_THROW(gui.frame([&] { EXPECT_EQ(verdict.draw(), VerdictAction::kNone); }));
}

// ---- verdict and note ----------------------------------------------------------------------------

TEST(RecordVerdictPanel, ShowsTheVerdictWithItsFiguresAndRedoAndNoteAreItsButtons) {
  ScratchSession s("record_panels_verdict");
  RecordState& model = *s.model;
  ASSERT_EQ(model.create(s.dir, spec_for("S04"), sim_settings(true)), "");
  ASSERT_EQ(model.override_preflight("checked by hand"), "");
  record_one_trial(model);
  const auto& a = *model.last_attempt();
  HeadlessImGui gui;
  RecordNotePanel note(s.model);
  RecordVerdictPanel panel(s.model, note);
  VerdictAction action = VerdictAction::kNone;
  const auto body = [&] {
    const VerdictAction v = panel.draw();
    if (v != VerdictAction::kNone) action = v;
  };
  const std::string text = gui.frame_text(body);
  const std::string name = model.state().trials.at(static_cast<size_t>(a.trial)).plan.name;
  EXPECT_TRUE(contains(text, name + ", attempt 1: " + a.outcome)) << text;
  EXPECT_TRUE(contains(text, a.verdict())) << text;
  EXPECT_TRUE(contains(text, "Recorded ")) << "the key figures: " << text;
  EXPECT_TRUE(contains(text, "Redo this trial  [R]")) << text;
  const auto redo = panel.anchors().centre("redo");
  ASSERT_TRUE(redo);
  gui.click(redo->x, redo->y, body);
  EXPECT_EQ(action, VerdictAction::kRedo);
  EXPECT_FALSE(note.awaiting_keyboard(ImGui::GetTime(), ImGui::GetFrameCount()));
  const auto note_button = panel.anchors().centre("note");
  ASSERT_TRUE(note_button);
  gui.click(note_button->x, note_button->y, body);
  EXPECT_TRUE(note.awaiting_keyboard(ImGui::GetTime(), ImGui::GetFrameCount()))
      << "the Note button opened the note line";
}

TEST(RecordNotePanel, TypedLettersAndEnterSubmitTheNoteOnTheTrial) {
  ScratchSession s("record_panels_note");
  ASSERT_EQ(s.model->create(s.dir, spec_for("S05"), sim_settings(true)), "");
  HeadlessImGui gui;
  RecordNotePanel note(s.model);
  bool submitted = false;
  const auto body = [&] { submitted = note.draw() || submitted; };
  EXPECT_EQ(gui.frame_text(body), "") << "closed: nothing drawn";
  note.open();
  EXPECT_TRUE(note.awaiting_keyboard(ImGui::GetTime(), ImGui::GetFrameCount()))
      << "the tab's shortcuts wait for the field";
  // A loaded machine: five seconds pass before the field has had a frame; the shortcuts still wait
  // (a Space typed into the note started a trial when only time bounded this).
  EXPECT_TRUE(note.awaiting_keyboard(ImGui::GetTime() + 5.0, ImGui::GetFrameCount() + 2));
  // A note line that is never drawn does not silence the shortcuts for good.
  EXPECT_FALSE(note.awaiting_keyboard(ImGui::GetTime() + 5.0, ImGui::GetFrameCount() + 30));
  gui.frames(3, body);
  EXPECT_FALSE(note.awaiting_keyboard(ImGui::GetTime(), ImGui::GetFrameCount())) << "the field has taken the keyboard";
  for (const char c : std::string("glove slipped")) {
    ImGui::GetIO().AddInputCharacter(static_cast<unsigned>(c));
    gui.frame(body);
  }
  EXPECT_FALSE(submitted);
  gui.tap_key(257, body);  // Enter
  EXPECT_TRUE(submitted);
  EXPECT_STREQ(note.text(), "glove slipped");
  EXPECT_EQ(s.model->add_note(note.text()), "");  // what the tab does with it
}

// ---- the block's calibration ---------------------------------------------------------------------

TEST(RecordCalibrationPanel, ACalibratingBlockOffersTheCalibrationThenItsResidualsAndApply) {
  ScratchSession s("record_panels_calibration");
  RecordState& model = *s.model;
  NewSessionSpec spec = spec_for("S06", "study-calibrated");
  spec.duration_override_s = 1.0;
  RecordSettings settings = sim_settings(true);
  settings.sim.calibration_random_translation_mm = 20;
  ASSERT_EQ(model.create(s.dir, spec, settings), "");
  ASSERT_EQ(model.override_preflight("checked by hand"), "");
  ASSERT_TRUE(model.needs_calibration());
  HeadlessImGui gui;
  RecordCalibrationPanel panel(s.model);
  TrialPanelAction action = TrialPanelAction::kNone;
  const auto body = [&] {
    const TrialPanelAction a = panel.draw();
    if (a != TrialPanelAction::kNone) action = a;
  };
  std::string text = gui.frame_text(body);
  EXPECT_TRUE(contains(text, "Calibrate layout '" + model.current_layout()->name + "' from the hand")) << text;
  EXPECT_FALSE(panel.anchors().centre("apply_calibration")) << "nothing to apply yet";
  const auto calibrate = panel.anchors().centre("calibrate");
  ASSERT_TRUE(calibrate);
  gui.click(calibrate->x, calibrate->y, body);
  EXPECT_EQ(action, TrialPanelAction::kCalibrate);
  ASSERT_EQ(model.start_calibration(), "");
  poll_until(model, [&] { return !model.busy() && model.pending_calibration().has_value(); });
  ASSERT_TRUE(model.pending_calibration());
  ASSERT_TRUE(model.pending_calibration()->ok()) << model.pending_calibration()->failure;
  text = gui.frame_text(body);
  EXPECT_TRUE(contains(text, "Apply  [Enter]")) << text;
  const auto apply = panel.anchors().centre("apply_calibration");
  ASSERT_TRUE(apply);
  gui.click(apply->x, apply->y, body);
  EXPECT_EQ(action, TrialPanelAction::kApplyCalibration);
}

// ---- device strips -------------------------------------------------------------------------------

TEST(RecordDeviceStripsPanel, ShowsEveryControllerOfTheRecordingTrial) {
  ScratchSession s("record_panels_strips");
  RecordState& model = *s.model;
  // Real time, so the trial is still recording when its snapshot is drawn.
  ASSERT_EQ(model.create(s.dir, spec_for("S07"), sim_settings(false)), "");
  ASSERT_EQ(model.override_preflight("checked by hand"), "");
  HeadlessImGui gui;
  RecordDeviceStripsPanel panel(s.model);
  EXPECT_EQ(gui.frame_text([&] { panel.draw(); }), "") << "no trial, no strips";
  ASSERT_EQ(model.start_trial(), "");
  poll_until(model, [&] { return model.live() && model.live()->phase == devices::TrialPhase::kRecording; });
  ASSERT_TRUE(model.live());
  const std::string text = gui.frame_text([&] { panel.draw(); });
  EXPECT_TRUE(contains(text, "Frames written")) << text;
  int controllers = 0;
  for (const auto& d : model.live()->hub.devices) {
    if (d.slot.empty()) continue;
    ++controllers;
    EXPECT_TRUE(contains(text, d.slot)) << d.slot << " in\n" << text;
    EXPECT_TRUE(contains(text, d.serial)) << d.serial << " in\n" << text;
  }
  EXPECT_GE(controllers, 2);
  model.stop_trial();
}

// ---- subject screen ------------------------------------------------------------------------------

TEST(SubjectScreenControlsPanel, TheToggleOpensTheSubjectScreenAndSaysHowToCloseIt) {
  HeadlessImGui gui;
  SubjectScreenLink link;
  link.monitors = {"DP-1 (1920x1080, primary)", "HDMI-1 (1920x1080)"};
  link.monitor_shorts = {"1: 1920x1080, primary", "2: 1920x1080"};
  link.placed_monitor = 1;  // the window's side placed it on the second monitor
  SubjectScreenControlsPanel panel(link);
  const auto body = [&] { panel.draw(); };
  std::string text = gui.frame_text(body);
  EXPECT_TRUE(contains(text, "Subject screen (F2)")) << text;
  EXPECT_TRUE(contains(text, "2: 1920x1080")) << "the monitor it opens on is shown: " << text;
  const auto toggle = panel.anchors().centre("toggle");
  ASSERT_TRUE(toggle);
  gui.click(toggle->x, toggle->y, body);
  EXPECT_TRUE(link.open);
  text = gui.frame_text(body);
  EXPECT_TRUE(contains(text, "Close subject screen (F2)")) << text;
}

// True when the frame drew a vertex of exactly this colour (the red circle's).
bool drew_colour(ImU32 colour) {
  const ImDrawData* data = ImGui::GetDrawData();
  for (int l = 0; l < data->CmdListsCount; ++l)
    for (const ImDrawVert& v : data->CmdLists[l]->VtxBuffer)
      if (v.col == colour) return true;
  return false;
}

TEST(SubjectScreenPanel, DrawsTheBigRedCircleOnlyWhileRecording) {
  HeadlessImGui gui(1280, 800);
  SubjectFonts fonts;
  fonts.normal = fonts.large = fonts.huge = ImGui::GetIO().Fonts->Fonts[0];
  TrialType type;
  type.duration_s = 3;
  type.subject_cue = "Bend your index finger";
  SubjectViewInputs in;
  in.has_session = true;
  in.type = &type;
  in.sim_motion = "horizontal/index";
  const ImU32 red = IM_COL32(230, 30, 30, 255);
  SubjectScreenLink link;
  SubjectScreenPanel panel(link);
  link.view = build_subject_view(in, 0);
  gui.frame([&] { panel.draw(fonts); });
  EXPECT_FALSE(drew_colour(red));
  in.phase = devices::TrialPhase::kRecording;
  link.view = build_subject_view(in, 0);
  gui.frame([&] { panel.draw(fonts); });
  EXPECT_TRUE(drew_colour(red));
}

// The lowest point drawn in this colour (0 when nothing was).
float lowest_y_of_colour(ImU32 colour) {
  float y = 0.0F;
  const ImDrawData* data = ImGui::GetDrawData();
  for (int l = 0; l < data->CmdListsCount; ++l)
    for (const ImDrawVert& v : data->CmdLists[l]->VtxBuffer)
      if (v.col == colour) y = std::max(y, v.pos.y);
  return y;
}

TEST(SubjectScreenPanel, TheCuesLastLineIsInsideAOneMonitorWindow) {
  // The 1024 × 640 window of a one-monitor bench, with the subject window's font sizes (28, 56
  // and 150 px; here ImGui's own font rasterised at those sizes) and the study's longest cue.
  HeadlessImGui gui(1024, 640);
  ImGuiIO& io = ImGui::GetIO();
  const auto add_font = [&io](float size_px) {
    ImFontConfig config;
    config.SizePixels = size_px;
    return io.Fonts->AddFontDefault(&config);
  };
  SubjectFonts fonts;
  fonts.normal = add_font(28);
  fonts.large = add_font(56);
  fonts.huge = add_font(150);
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  TrialType type;
  type.duration_s = 5;
  type.subject_cue = "Bend your index finger fully and straighten it again, slowly, until the circle disappears.";
  ProtocolPose pose;
  pose.cue = "palm facing down";
  SubjectViewInputs in;
  in.has_session = true;
  in.type = &type;
  in.pose = &pose;
  in.sim_motion = "horizontal/index";
  in.phase = devices::TrialPhase::kRecording;
  SubjectScreenLink link;
  link.view = build_subject_view(in, 0);
  SubjectScreenPanel panel(link);
  gui.frame([&] { panel.draw(fonts); });
  const float cue_bottom = lowest_y_of_colour(IM_COL32(255, 230, 130, 255));
  const float hand_bottom = lowest_y_of_colour(IM_COL32(130, 130, 135, 255));
  EXPECT_GT(cue_bottom, 320.0F);  // drawn, below the circle
  EXPECT_LE(cue_bottom, 640.0F);
  EXPECT_GT(hand_bottom, cue_bottom);  // the hand line follows the cue, inside the window too
  EXPECT_LE(hand_bottom, 640.0F);
}

}  // namespace record_panels_test
}  // namespace lmc::ui
