// Headless tests of the Record tab's set-up panel, pre-flight section and subject screen: clicks
// go through ImGuiIO to the real panels, which are drawn without a renderer.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "tests/support/scratch_dir.h"
#include "tests/ui/headless_imgui.h"
#include "ui/model/record/record_session_model.h"
#include "ui/model/record/record_setup_form.h"
#include "ui/model/record/subject_view.h"
#include "ui/tabs/record/record_setup_panel.h"
#include "ui/tabs/record/record_trial_panel.h"
#include "ui/tabs/record/record_verdict_panel.h"
#include "ui/tabs/record/subject_screen_panel.h"

namespace lmc::ui {
namespace record_panels_test {  // named: test files share unity batches

namespace fs = std::filesystem;
using testing::HeadlessImGui;

TEST(RecordSetupPanel, CreateStaysDisabledUntilTheSubjectIdIsSafe) {
  HeadlessImGui gui;
  RecordSetupForm form;
  std::snprintf(form.subject, sizeof form.subject, "%s", "S 01/x");
  WidgetAnchors anchors;
  SetupAction action = SetupAction::kNone;
  const auto body = [&] {
    const SetupAction a = draw_record_setup_panel(form, check_setup_form(form), {}, "", &anchors);
    if (a != SetupAction::kNone) action = a;
  };
  gui.frame(body);
  ASSERT_TRUE(anchors.centre("create"));
  const ImVec2 create = *anchors.centre("create");
  gui.click(create.x, create.y, body);
  EXPECT_EQ(action, SetupAction::kNone);  // refused: the form says why under the field
  std::snprintf(form.subject, sizeof form.subject, "%s", "S01");
  gui.frame(body);
  const ImVec2 create_now = *anchors.centre("create");
  gui.click(create_now.x, create_now.y, body);
  EXPECT_EQ(action, SetupAction::kCreate);
}

TEST(RecordTrialPanel, StartIsEnabledOnlyAfterThePreflightOrAnOverrideWithAReason) {
  const fs::path dir = test::fresh_test_dir("record_panels");
  RecordSessionModel model;
  session::NewSessionSpec spec;
  spec.subject.subject_id = "S01";
  spec.protocol = "quick";
  RecordSettings settings;
  settings.fast = true;
  settings.countdown_s = 0;
  ASSERT_EQ(model.create(dir, spec, settings), "");
  HeadlessImGui gui;
  TrialPanelInput input;
  TrialPanelAction action = TrialPanelAction::kNone;
  const auto body = [&] {
    const TrialPanelAction a = draw_record_trial_panel(model, input);
    if (a != TrialPanelAction::kNone) action = a;
  };
  gui.frame(body);
  // Before the pre-flight Space has one meaning and one button: Run pre-flight. No Start is drawn.
  EXPECT_FALSE(input.anchors.centre("start"));
  ASSERT_TRUE(input.anchors.centre("preflight"));
  EXPECT_NE(model.override_preflight(""), "");  // no reason, no override
  EXPECT_TRUE(model.needs_preflight());
  ASSERT_EQ(model.override_preflight("controllers checked by hand"), "");
  input.anchors = {};
  gui.frame(body);
  ASSERT_TRUE(input.anchors.centre("start"));
  EXPECT_FALSE(input.anchors.centre("preflight"));
  const ImVec2 start = *input.anchors.centre("start");
  gui.click(start.x, start.y, body);
  EXPECT_EQ(action, TrialPanelAction::kStart);
  EXPECT_EQ(model.start_trial(), "");  // and the model agrees
  model.close();
  fs::remove_all(dir);
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
  session::TrialType type;
  type.duration_s = 3;
  type.subject_cue = "Bend your index finger";
  SubjectViewInputs in;
  in.has_session = true;
  in.type = &type;
  in.sim_motion = "horizontal/index";
  const ImU32 red = IM_COL32(230, 30, 30, 255);
  const SubjectView ready = build_subject_view(in, 0);
  gui.frame([&] { draw_subject_screen(ready, fonts); });
  EXPECT_FALSE(drew_colour(red));
  in.phase = devices::TrialPhase::kRecording;
  const SubjectView recording = build_subject_view(in, 0);
  gui.frame([&] { draw_subject_screen(recording, fonts); });
  EXPECT_TRUE(drew_colour(red));
}

TEST(RecordTrialPanel, AfterCloseAndReopenNothingOfTheLastVerdictIsDrawnAgainstAnEmptyList) {
  const fs::path dir = test::fresh_test_dir("record_panels_close");
  RecordSessionModel model;
  session::NewSessionSpec spec;
  spec.subject.subject_id = "S02";
  spec.protocol = "quick";
  RecordSettings settings;
  settings.fast = true;
  settings.countdown_s = 0;
  ASSERT_EQ(model.create(dir, spec, settings), "");
  ASSERT_EQ(model.override_preflight("checked by hand"), "");
  ASSERT_EQ(model.start_trial(), "");
  for (int k = 0; k < 6000 && !(model.last_attempt() && !model.busy()); ++k) {
    model.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(model.last_attempt());
  HeadlessImGui gui;
  NoteInput note;
  model.close();
  // The Record tab drew the verdict in the frame of Close: the attempt's trial index into a
  // closed session's (empty) trial list threw std::out_of_range and ended the program.
  EXPECT_NO_THROW(gui.frame([&] { EXPECT_EQ(draw_record_verdict_panel(model, note), VerdictAction::kNone); }));
  ASSERT_EQ(model.open(dir, settings), "");
  TrialPanelInput input;
  EXPECT_NO_THROW(gui.frame([&] { draw_record_trial_panel(model, input); }));
  EXPECT_NO_THROW(gui.frame([&] { EXPECT_EQ(draw_record_verdict_panel(model, note), VerdictAction::kNone); }));
  model.close();
  fs::remove_all(dir);
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
  session::TrialType type;
  type.duration_s = 5;
  type.subject_cue = "Bend your index finger fully and straighten it again, slowly, until the circle disappears.";
  session::ProtocolPose pose;
  pose.cue = "palm facing down";
  SubjectViewInputs in;
  in.has_session = true;
  in.type = &type;
  in.pose = &pose;
  in.sim_motion = "horizontal/index";
  in.phase = devices::TrialPhase::kRecording;
  const SubjectView recording = build_subject_view(in, 0);
  gui.frame([&] { draw_subject_screen(recording, fonts); });
  const float cue_bottom = lowest_y_of_colour(IM_COL32(255, 230, 130, 255));
  const float hand_bottom = lowest_y_of_colour(IM_COL32(130, 130, 135, 255));
  EXPECT_GT(cue_bottom, 320.0F);  // drawn, below the circle
  EXPECT_LE(cue_bottom, 640.0F);
  EXPECT_GT(hand_bottom, cue_bottom);  // the hand line follows the cue, inside the window too
  EXPECT_LE(hand_bottom, 640.0F);
}

}  // namespace record_panels_test
}  // namespace lmc::ui
