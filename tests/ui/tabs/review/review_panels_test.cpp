// Headless tests of the Review tab's panels (Export... has its own file): each is drawn on a real
// ReviewState that opened a quick simulated subject session (two trials, with Vicon), and clicks
// go through ImGuiIO to the panel, which is drawn without a renderer.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "core/common/paths.h"
#include "tests/support/cli_runner.h"
#include "tests/support/quick_session.h"
#include "tests/support/scratch_dir.h"
#include "tests/ui/headless_imgui.h"
#include "ui/model/review/review_state.h"
#include "ui/tabs/review/review_agreement_panel.h"
#include "ui/tabs/review/review_open_panel.h"
#include "ui/tabs/review/review_replay_panel.h"
#include "ui/tabs/review/review_sources_panel.h"
#include "ui/tabs/review/review_study_tables_panel.h"
#include "ui/tabs/review/review_trial_table_panel.h"
#include "ui/tabs/review/review_trial_view_panel.h"
#include "ui/tabs/review/review_welcome_panel.h"

namespace lmc::ui {
namespace review_panels_test {  // named: test files share unity batches

namespace fs = std::filesystem;
using testing::HeadlessImGui;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class ReviewPanels : public test::QuickSessionSuite<ReviewPanels> {
 public:
  static constexpr const char* kScratchName = "review_panels";
  static constexpr int kSeed = 6;

 protected:
  ReviewPanels() {
    state->set_cache_dir(root() / "cache");  // shared: later tests' batches come from it
    // The trial view's plots pass 64k vertices in one window: the workbench's OpenGL renderer
    // draws such lists in parts (vertex offsets), and so does this headless one, which draws nothing.
    ImGui::GetIO().BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
  }

  // Updates the state (as the tab does once a frame) until `done`, for at most two minutes.
  bool update_until(const std::function<bool()>& done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    for (;;) {
      state->update();
      if (done()) return true;
      if (std::chrono::steady_clock::now() > deadline) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  // Opens the session and waits for its batch and the selected trial's view.
  void open_session() {
    state->open_folder(session());
    ASSERT_TRUE(update_until([&] { return state->batch() != nullptr && !state->batch_job().running(); }));
    ASSERT_EQ(state->trials().size(), 2u);
    ASSERT_GE(state->selected(), 0);  // the first trial with Vicon is selected for the view
    ASSERT_TRUE(update_until([&] { return state->view() != nullptr; })) << state->view_job().error();
  }
  // Draws `draw` for a frame, then clicks the centre of its anchor `name`.
  template <typename Panel>
  void click(const Panel& panel, const std::string& name, const std::function<void()>& draw) {
    const auto body = [&] {
      state->update();
      draw();
    };
    gui.frame(body);
    const auto c = panel.anchors().centre(name);
    ASSERT_TRUE(c.has_value()) << name << " is not on screen";
    gui.click(c->x, c->y, body);
  }

  std::shared_ptr<ReviewState> state = std::make_shared<ReviewState>();
  HeadlessImGui gui;
};

TEST_F(ReviewPanels, WelcomeSaysWhatTheTabDoesAndOffersTheOpenButtons) {
  ReviewWelcomePanel panel(state);
  const std::string text = gui.frame_text([&] { panel.draw(); });
  EXPECT_TRUE(contains(text, "Review processed trials against Vicon")) << text;
  EXPECT_TRUE(contains(text, "Open folder...")) << text;
  EXPECT_TRUE(panel.open_panel().anchors().fully_visible("open"));
  EXPECT_TRUE(state->folders().empty());
}

TEST_F(ReviewPanels, OpenPanelsStudySampleButtonOpensTheSampleTrial) {
  ReviewOpenPanel panel(state);
  gui.frame([&] { panel.draw(); });
  if (study_sample_dir().empty()) {
    // Without the study's sample the button is not drawn at all.
    EXPECT_FALSE(panel.anchors().centre("sample").has_value());
    return;
  }
  click(panel, "sample", [&] { panel.draw(); });
  ASSERT_EQ(state->folders().size(), 1u);
  EXPECT_EQ(state->folders().front(), study_sample_dir());
}

TEST_F(ReviewPanels, SourcesBarNamesTheOpenFolderAndWhatItsBatchDidAndClosesIt) {
  open_session();
  ReviewSourcesPanel panel(state);
  const std::string text = gui.frame_text([&] { panel.draw(); });
  EXPECT_TRUE(contains(text, "[S01")) << text;
  EXPECT_TRUE(contains(text, "fusion")) << text;
  EXPECT_TRUE(contains(text, "2 trial(s): ")) << text;
  EXPECT_TRUE(panel.anchors().fully_visible("lengths.S01"));
  click(panel, "close.S01", [&] { panel.draw(); });
  EXPECT_TRUE(state->folders().empty());
}

TEST_F(ReviewPanels, TrialTableShowsEveryTrialFiltersThemAndSelectsTheOneClicked) {
  open_session();
  ReviewTrialTablePanel panel(state);
  std::string text = gui.frame_text([&] { panel.draw(); });
  EXPECT_TRUE(contains(text, "2 of 2")) << text;
  EXPECT_TRUE(contains(text, "length diff (mm)")) << text;
  for (const auto& t : state->trials()) EXPECT_TRUE(contains(text, t.row.trial)) << t.row.trial << " in " << text;
  const int other = state->selected() == 0 ? 1 : 0;
  click(panel, "trial." + std::to_string(other), [&] { panel.draw(); });
  EXPECT_EQ(state->selected(), other);
  TrialFilter none;
  none.subject = "nobody";
  state->set_filter(none);
  text = gui.frame_text([&] { panel.draw(); });
  EXPECT_TRUE(contains(text, "0 of 2")) << text;
  EXPECT_FALSE(panel.anchors().centre("trial.0").has_value());
  EXPECT_FALSE(panel.anchors().centre("trial.1").has_value());
}

TEST_F(ReviewPanels, TrialViewShowsTheSelectedTrialAgainstViconWithItsLabelStrips) {
  open_session();
  ReviewTrialViewPanel panel(state);
  const PictureRenderer no_renderer;
  const std::string text = gui.frame_text([&] { panel.draw(no_renderer); });
  const std::string trial = state->view()->series.trial;
  EXPECT_TRUE(contains(text, trial)) << text;
  EXPECT_TRUE(contains(text, "default fusion")) << text;
  EXPECT_TRUE(contains(text, "against Vicon")) << text;
  EXPECT_TRUE(contains(text, "Ray-traced labels per controller")) << text;
  EXPECT_FALSE(panel.each_controller());
  click(panel, "each_controller", [&] { panel.draw(no_renderer); });
  EXPECT_TRUE(panel.each_controller());
}

TEST_F(ReviewPanels, ReplayPlaysFromTheCursorAndSaysPause) {
  open_session();
  ReviewReplayPanel panel(state);
  std::string text = gui.frame_text([&] { panel.draw(); });
  EXPECT_TRUE(contains(text, "Play")) << text;
  EXPECT_FALSE(panel.playing());
  click(panel, "play", [&] { panel.draw(); });
  EXPECT_TRUE(panel.playing());
  text = gui.frame_text([&] { panel.draw(); });
  EXPECT_TRUE(contains(text, "Pause")) << text;
  EXPECT_TRUE(state->x_range()->cursor.has_value());
}

TEST_F(ReviewPanels, AgreementTabulatesTheShownTrialsAndSelectsAMeasure) {
  open_session();
  ReviewAgreementPanel panel(state);
  const PictureRenderer no_renderer;
  const std::string text = gui.frame_text([&] { panel.draw(no_renderer); });
  EXPECT_TRUE(contains(text, "Across the 2 trial(s) the table shows")) << text;
  EXPECT_TRUE(contains(text, "bias LMC-Vicon [95% CI]")) << text;
  EXPECT_TRUE(contains(text, "Visibility rate per controller")) << text;
  ASSERT_FALSE(state->agreement().table.groups.empty());
  ASSERT_GE(state->agreement().table.groups.back().measures.size(), 2u);
  EXPECT_EQ(panel.measure(), 0);
  click(panel, "measure.1", [&] { panel.draw(no_renderer); });
  EXPECT_EQ(panel.measure(), 1);
}

TEST_F(ReviewPanels, StudyTablesShowTheHeadlineTablesOfTheShownTrials) {
  ReviewStudyTablesPanel panel(state);
  std::string text = gui.frame_text([&] { panel.draw(); });
  EXPECT_TRUE(contains(text, "No processed trial among those shown.")) << text;
  open_session();
  text = gui.frame_text([&] { panel.draw(); });
  EXPECT_FALSE(contains(text, "No processed trial among those shown.")) << text;
  EXPECT_TRUE(contains(text, "Processing report")) << text;  // lmc report's heading
  EXPECT_TRUE(contains(text, "2 trial(s), 2 with Vicon.")) << text;
  EXPECT_FALSE(state->agreement().study_tables.empty());
}

}  // namespace review_panels_test
}  // namespace lmc::ui
