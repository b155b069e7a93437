// The Layout tab's Timeline and Heatmap panels drawn headless on a small pose set: what each
// shows, what a click changes, and the timeline's two-row form in a narrow scene, where nothing
// is cut (ui/app/capture/text_fit_check.h).
#include <gtest/gtest.h>
#include <imgui.h>

#include <memory>
#include <string>

#include "tests/ui/headless_imgui.h"
#include "ui/app/capture/text_fit_check.h"
#include "ui/model/layout/layout_actions.h"
#include "ui/model/layout/layout_state.h"
#include "ui/tabs/layout/heatmap_panel.h"
#include "ui/tabs/layout/timeline_panel.h"

namespace lmc::ui {
namespace {

using testing::HeadlessImGui;

std::shared_ptr<LayoutState> state_with_poses(int frames) {
  auto state = std::make_shared<LayoutState>(make_document(default_new_layout()));
  PoseSetChoice c;
  c.frames = frames;
  c.seed = 7;
  EXPECT_TRUE(set_pose_set_choice(state->upd_history(), c));
  state->update(0.0);
  state->poses.wait();
  state->update(0.0);
  return state;
}

std::string cuts_text() {
  std::string s;
  for (const auto& c : find_cut_text()) s += describe(c) + "\n";
  return s;
}

TEST(TimelinePanel, ShowsTheFrameAndCountAndPlayToggles) {
  HeadlessImGui gui;
  auto state = state_with_poses(40);
  TimelinePanel panel(state);
  const auto draw = [&] { panel.draw(); };
  gui.frames(2, draw);
  const std::string text = gui.frame_text(draw);
  EXPECT_NE(text.find("40 of 40"), std::string::npos) << text;
  EXPECT_NE(text.find("Play"), std::string::npos) << text;
  EXPECT_FLOAT_EQ(panel.height(1264), ImGui::GetFrameHeightWithSpacing());  // one row at 1280
  EXPECT_FALSE(state->timeline.playing);
  gui.click(30, 18, draw);  // Play, first on the row
  EXPECT_TRUE(state->timeline.playing);
  EXPECT_TRUE(find_cut_text().empty()) << cuts_text();
}

TEST(TimelinePanel, InANarrowSceneTheFiltersGoUnderTheSliderAndNothingIsCut) {
  HeadlessImGui gui(540, 400);  // the scene's width in a 1024-pixel window
  auto state = state_with_poses(40);
  TimelinePanel panel(state);
  const float width = 540 - 2 * ImGui::GetStyle().WindowPadding.x;
  EXPECT_FLOAT_EQ(panel.height(width), 2 * ImGui::GetFrameHeight() + ImGui::GetStyle().ItemSpacing.y);
  gui.frames(3, [&] { panel.draw(); });
  EXPECT_TRUE(find_cut_text().empty()) << cuts_text();
  EXPECT_NE(gui.frame_text([&] { panel.draw(); }).find("40 of 40"), std::string::npos);
}

TEST(HeatmapPanel, NamesTheControllerItSweepsAndItsCheckboxHidesTheHeatmap) {
  HeadlessImGui gui;
  auto state = state_with_poses(40);
  HeatmapPanel panel(state);
  const auto draw = [&] { panel.draw(); };
  state->select(-1);
  EXPECT_NE(gui.frame_text(draw).find("Select a controller to sweep."), std::string::npos);
  state->select(0);
  const std::string text = gui.frame_text(draw);
  EXPECT_NE(text.find("Controller: " + state->layout().devices[0].slot), std::string::npos) << text;
  EXPECT_NE(text.find("frames added (seen by no other)"), std::string::npos) << text;
  const bool shown = state->display.show_heatmap;
  gui.click(16, 18, draw);  // "Show the heatmap on the table", the first line
  EXPECT_NE(state->display.show_heatmap, shown);
}

}  // namespace
}  // namespace lmc::ui
