// Headless tests of Review → Export… (the real ImGui panel, input fed through ImGuiIO): a quick
// simulated subject session is opened in a ReviewState; the selected trial is exported as C3D and
// the finished export offers its folder; an export that would replace a file shows why it wrote
// nothing, and goes through once replacing is ticked; a running export is cancelled from its
// progress row; the window's controls fit a 1280×800 screen.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>

#include "core/export/bids_dataset_files.h"
#include "core/io/c3d.h"
#include "tests/support/cli_runner.h"
#include "tests/support/quick_session.h"
#include "tests/support/scratch_dir.h"
#include "tests/ui/headless_imgui.h"
#include "ui/model/review/review_state.h"
#include "ui/tabs/review/review_export_panel.h"

namespace lmc::ui {
namespace review_export_panel_test {  // named: test files share unity batches

namespace fs = std::filesystem;
using testing::HeadlessImGui;

class ExportPanel : public test::QuickSessionSuite<ExportPanel> {
 public:
  static constexpr const char* kScratchName = "review_export_panel";
  static constexpr int kSeed = 6;

 protected:
  void SetUp() override {
    state->set_cache_dir(root() / "cache");  // shared: the second test's batch comes from the cache
    state->open_folder(session());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while ((state->batch() == nullptr || state->batch_job().running()) && std::chrono::steady_clock::now() < deadline) {
      state->update();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ASSERT_NE(state->batch(), nullptr);
    ASSERT_EQ(state->trials().size(), 2u);
    ASSERT_GE(state->selected(), 0);  // the first trial with Vicon is selected for the view
  }

  std::function<void()> body() {
    return [this] {
      state->update();
      panel.draw_button();
      panel.draw_window();
    };
  }
  void click(const std::string& anchor) {
    gui.frame(body());
    const auto c = panel.anchors().centre(anchor);
    ASSERT_TRUE(c.has_value()) << anchor << " is not on screen";
    gui.click(c->x, c->y, body());
  }
  void wait_while_exporting() {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (state->motion_export().running() && std::chrono::steady_clock::now() < deadline) {
      gui.frame(body());
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    gui.frames(2, body());
  }

  HeadlessImGui gui;
  std::shared_ptr<ReviewState> state = std::make_shared<ReviewState>();
  std::vector<fs::path> opened;
  ReviewExportPanel panel{state, [this](const fs::path& folder, std::string*) {
                            opened.push_back(folder);
                            return true;
                          }};
};

TEST_F(ExportPanel, ExportsTheSelectedTrialAsC3dAndOffersItsFolder) {
  click("export.button");
  ASSERT_TRUE(panel.is_open());
  for (const char* a : {"export.what.selected", "export.what.shown", "export.what.bids", "export.format", "export.axes",
                        "export.folder", "export.replace", "export.start"}) {
    EXPECT_TRUE(panel.anchors().fully_visible(a)) << a << " is cut off at 1280x800";
  }
  click("export.what.selected");
  const fs::path out = test::scratch_dir("review_export_selected") / "one";
  panel.set_folder(out);
  click("export.start");
  wait_while_exporting();
  ASSERT_EQ(state->motion_export().state(), JobState::kCompleted) << state->motion_export().error();
  const std::string trial = state->trials()[static_cast<size_t>(state->selected())].job.trial;
  const fs::path file = out / (trial + ".c3d");
  ASSERT_TRUE(fs::exists(file));
  EXPECT_GT(read_c3d(file).frame_count(), 100);
  // Only the selected one.
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator{}), 1);
  EXPECT_TRUE(panel.anchors().fully_visible("export.result"));
  EXPECT_FALSE(panel.anchors().centre("export.error").has_value());
  click("export.open_folder");
  EXPECT_EQ(opened, std::vector<fs::path>{out});
}

TEST_F(ExportPanel, AnExportThatWouldReplaceAFileSaysWhyAndGoesThroughWhenReplacing) {
  const fs::path out = test::scratch_dir("review_export_exists");
  const fs::path existing = out / (state->trials()[0].job.trial + ".c3d");
  std::ofstream(existing) << "an older export";
  panel.open();
  panel.choose(ReviewExportPanel::What::kShown);
  panel.set_folder(out);
  click("export.start");
  wait_while_exporting();
  EXPECT_EQ(state->motion_export().state(), JobState::kFailed);
  EXPECT_NE(state->motion_export().error().find(existing.string()), std::string::npos)
      << state->motion_export().error();
  EXPECT_TRUE(panel.anchors().fully_visible("export.error"));
  EXPECT_FALSE(panel.anchors().centre("export.open_folder").has_value());
  EXPECT_EQ(test::read_text_file(existing), "an older export");
  click("export.replace");
  click("export.start");
  wait_while_exporting();
  ASSERT_EQ(state->motion_export().state(), JobState::kCompleted) << state->motion_export().error();
  EXPECT_EQ(state->motion_export().outcome()->trials, 2);
  EXPECT_GT(read_c3d(existing).frame_count(), 100);
  EXPECT_FALSE(panel.anchors().centre("export.error").has_value());
}

TEST_F(ExportPanel, CancelStopsARunningExportAndTheWindowSaysWhatWasWritten) {
  panel.open();
  panel.choose(ReviewExportPanel::What::kShown);
  const fs::path out = test::scratch_dir("review_export_cancel") / "both";
  panel.set_folder(out);
  click("export.start");
  ASSERT_TRUE(state->motion_export().running()) << "the export ended before Cancel could be pressed";
  click("export.progress.cancel");
  wait_while_exporting();
  EXPECT_EQ(state->motion_export().state(), JobState::kCancelled);
  const auto outcome = state->motion_export().outcome();
  ASSERT_TRUE(outcome);
  EXPECT_TRUE(outcome->cancelled);
  EXPECT_LT(outcome->trials, 2);
  EXPECT_TRUE(panel.anchors().centre("export.result").has_value());
  // Whatever was written before the stop is whole.
  for (const auto& file : outcome->written) EXPECT_GT(read_c3d(file).frame_count(), 100);
}

// Exports each in their own place: after a BIDS export, choosing the selected trial brings back a
// per-trial folder, never the dataset's; a per-trial export typed into the dataset is refused, saying
// why, and writes nothing there.
TEST_F(ExportPanel, APerTrialExportNeverLandsInABidsDataset) {
  panel.open();
  click("export.what.bids");
  const fs::path dataset = test::scratch_dir("review_export_bids_then_c3d") / "dataset";
  fs::remove_all(dataset);
  panel.set_folder(dataset);
  click("export.start");
  wait_while_exporting();
  ASSERT_EQ(state->motion_export().state(), JobState::kCompleted) << state->motion_export().error();
  ASSERT_TRUE(fs::exists(dataset / "dataset_description.json"));
  click("export.what.selected");
  EXPECT_NE(panel.folder(), dataset) << "the per-trial export kept the dataset's folder";
  EXPECT_TRUE(bids_dataset_root_of(panel.folder()).empty()) << panel.folder();
  click("export.what.bids");
  EXPECT_EQ(panel.folder(), dataset) << "the dataset's folder comes back with the BIDS choice";

  click("export.what.selected");
  panel.set_folder(dataset / "sub-S01");
  click("export.start");
  wait_while_exporting();
  EXPECT_EQ(state->motion_export().state(), JobState::kFailed);
  const std::string error = state->motion_export().error();
  EXPECT_NE(error.find("lies in the BIDS dataset " + dataset.string()), std::string::npos) << error;
  EXPECT_TRUE(panel.anchors().fully_visible("export.error"));
  for (const auto& e : fs::recursive_directory_iterator(dataset)) EXPECT_NE(e.path().extension(), ".c3d") << e.path();
}

}  // namespace review_export_panel_test
}  // namespace lmc::ui
