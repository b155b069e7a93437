// Headless tests of the Devices tab's panels (the Calibrate panel has its own file): each is
// drawn with a real DevicesState on the workbench's live rig running the simulated controllers,
// and clicks go through ImGuiIO to the panel, which is drawn without a renderer.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/io/layout_json.h"
#include "tests/support/reference_data.h"
#include "tests/support/scratch_dir.h"
#include "tests/ui/headless_imgui.h"
#include "ui/model/devices/devices_state.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/devices/device_log_panel.h"
#include "ui/tabs/devices/device_table_panel.h"
#include "ui/tabs/devices/devices_toolbar_panel.h"
#include "ui/tabs/devices/live_hands_panel.h"
#include "ui/tabs/devices/test_recording_panel.h"

namespace lmc::ui {
namespace devices_panels_test {  // named: test files share unity batches

using testing::HeadlessImGui;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The workbench's context with the paper's initial layout published (as the Layout tab does),
// and the Devices tab's state on its rig; status lines are kept.
class DevicesPanels : public ::testing::Test {
 protected:
  DevicesPanels() {
    context.layout().publish(load_layout(test::asset_file("layouts/paper-initial.json")));
    state = std::make_shared<DevicesState>(
        context.rig(), context.layout(),
        [this](const std::string& text, bool is_error) { lines.emplace_back(text, is_error); });
  }
  ~DevicesPanels() override { state->stop(); }

  // Updates the state (as the tab does once a frame) until `done`, for at most `timeout_s`.
  bool update_until(const std::function<bool()>& done, double timeout_s = 20.0) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    for (;;) {
      state->update();
      if (done()) return true;
      if (std::chrono::steady_clock::now() > deadline) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  bool said(const std::string& text) const {
    for (const auto& [line, is_error] : lines)
      if (contains(line, text)) return true;
    return false;
  }
  void start_sim() {
    ASSERT_EQ(state->start("sim"), "");
    ASSERT_TRUE(update_until([&] { return state->view().rows().size() == 4; })) << "four simulated controllers";
  }

  WorkbenchContext context;  // first: outlives the state, which drives its rig
  std::vector<std::pair<std::string, bool>> lines;
  std::shared_ptr<DevicesState> state;
  HeadlessImGui gui;
};

TEST_F(DevicesPanels, ToolbarStartRunsTheChosenBackendAndStopStopsIt) {
  DevicesToolbarPanel panel(state);
  const auto body = [&] {
    state->update();  // as the tab does before drawing: the rig takes the published layout
    panel.draw();
  };
  std::string text = gui.frame_text(body);
  EXPECT_TRUE(contains(text, "paper-initial")) << "the layout the rig runs: " << text;
  EXPECT_FALSE(state->view().running());
  auto start = panel.anchors().centre("start");
  ASSERT_TRUE(start);
  gui.click(start->x, start->y, body);
  EXPECT_TRUE(state->view().running());
  EXPECT_EQ(state->view().backend(), "sim");
  gui.move_to(1270, 790);  // off the buttons: no tooltip over the line
  text = gui.frame_text(body);
  EXPECT_TRUE(contains(text, "sim running")) << text;
  const auto stop = panel.anchors().centre("stop");
  ASSERT_TRUE(stop);
  gui.click(stop->x, stop->y, body);
  EXPECT_FALSE(state->view().running());
}

// The backend dropdown's text: the first word after "Backend" on the toolbar's line (a combo's
// text reads "{ sim }").
std::string backend_shown(const std::string& toolbar_text) {
  const size_t at = toolbar_text.find("Backend");
  if (at == std::string::npos) return {};
  const size_t from = toolbar_text.find_first_not_of(" {\n", at + 7);
  return from == std::string::npos ? std::string()
                                   : toolbar_text.substr(from, toolbar_text.find_first_of(" \n", from) - from);
}

TEST_F(DevicesPanels, ToolbarDropdownShowsTheBackendThatRuns) {
  // Started without the toolbar (the automatic LeapC start, or a start from another tab): the
  // dropdown must name what runs, not its own default.
  const auto path = test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  DevicesToolbarPanel panel(state);
  const auto body = [&] {
    state->update();
    panel.draw();
  };
  EXPECT_EQ(backend_shown(gui.frame_text(body)), "sim") << "nothing runs: the default";
  ASSERT_EQ(state->start("replay:" + path.string()), "");
  gui.move_to(1270, 790);
  std::string text = gui.frame_text(body);
  EXPECT_EQ(backend_shown(text), "replay") << text;
  EXPECT_TRUE(contains(text, path.filename().string())) << "the replayed file in its field: " << text;
  start_sim();  // as the fallback to the simulated rig does
  text = gui.frame_text(body);
  EXPECT_EQ(backend_shown(text), "sim") << text;
}

TEST_F(DevicesPanels, ToolbarStartThatWorksReplacesAnEarlierError) {
  DevicesToolbarPanel panel(state);
  const auto body = [&] {
    state->update();
    panel.draw();
  };
  EXPECT_NE(state->start("replay:/nonexistent/LMC_x.raw.txt"), "");
  ASSERT_FALSE(lines.empty());
  EXPECT_TRUE(lines.back().second) << "a failed start is an error: " << lines.back().first;
  gui.frame(body);
  const auto start = panel.anchors().centre("start");
  ASSERT_TRUE(start);
  gui.click(start->x, start->y, body);
  ASSERT_TRUE(state->view().running());
  ASSERT_FALSE(lines.empty());
  EXPECT_FALSE(lines.back().second) << "the error stayed after Start worked: " << lines.back().first;
  EXPECT_TRUE(contains(lines.back().first, "started sim")) << lines.back().first;
}

TEST_F(DevicesPanels, DeviceTableHasARowPerControllerWithItsSerialSlotAndStatus) {
  DeviceTablePanel panel(state);
  EXPECT_TRUE(contains(gui.frame_text([&] { panel.draw(); }), "no backend running: press Start"));
  start_sim();
  const std::string text = gui.frame_text([&] { panel.draw(); });
  for (const DeviceRow& r : state->view().rows()) {
    EXPECT_TRUE(contains(text, r.serial)) << r.serial << " in\n" << text;
    EXPECT_TRUE(contains(text, r.slot)) << r.slot << " in\n" << text;
  }
  EXPECT_TRUE(contains(text, "Frame age")) << text;
}

TEST_F(DevicesPanels, TestRecordingRecordsIntoTheFolderAndStopInterruptsIt) {
  const std::filesystem::path dir = test::fresh_test_dir("devices_panels_recording");
  TestRecordingPanel panel(state, dir);
  const auto body = [&] { panel.draw(); };
  start_sim();
  gui.frame(body);
  const auto record = panel.anchors().centre("record");
  ASSERT_TRUE(record);
  gui.click(record->x, record->y, body);
  EXPECT_TRUE(state->view().recording());
  EXPECT_TRUE(said("recording test_trial_1"));
  ASSERT_TRUE(update_until(
      [&] { return state->view().recording_progress() && state->view().recording_progress()->frames_written > 0; }));
  EXPECT_TRUE(contains(gui.frame_text(body), "test_trial_1: "));
  const auto stop = panel.anchors().centre("stop_recording");
  ASSERT_TRUE(stop);
  gui.click(stop->x, stop->y, body);
  ASSERT_TRUE(update_until([&] { return !state->view().recording() && said("interrupted"); }));
  bool wrote = false;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    wrote = wrote || contains(e.path().filename().string(), "test_trial_1");
  EXPECT_TRUE(wrote) << "the interrupted trial's rows are kept in " << dir;
  std::filesystem::remove_all(dir);
}

TEST_F(DevicesPanels, LiveHandsShowsTheFusionLatencyAndADragOrbitsItsCamera) {
  LiveHandsPanel panel(state);
  const auto body = [&] { panel.draw(); };
  EXPECT_FALSE(contains(gui.frame_text(body), "fusion")) << "no rig, no latency line";
  start_sim();
  ASSERT_TRUE(update_until([&] { return state->view().fusion_stats().window_frames > 0; }));
  EXPECT_TRUE(contains(gui.frame_text(body), "fusion latency")) << "the latency over the view";
  const double yaw = panel.camera().yaw_deg();
  gui.drag(ImVec2(640, 400), ImVec2(760, 400), 6, body);
  EXPECT_NE(panel.camera().yaw_deg(), yaw) << "a drag across the view orbits it";
}

TEST_F(DevicesPanels, DeviceLogShowsTheRigsMessages) {
  DeviceLogPanel panel(state);
  start_sim();
  ASSERT_FALSE(state->view().messages().empty());
  const std::string text = gui.frame_text([&] { panel.draw(); });
  EXPECT_TRUE(contains(text, "Device messages"));
  EXPECT_TRUE(contains(text, state->view().messages().back())) << text;
}

}  // namespace devices_panels_test
}  // namespace lmc::ui
