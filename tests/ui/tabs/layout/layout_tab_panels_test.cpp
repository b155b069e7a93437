// Headless tests of the Layout tab's real ImGui panels: mouse and keys are fed through ImGuiIO,
// frames are run without a renderer, and the scene panel gets a recording renderer.
#include <gtest/gtest.h>

#include <algorithm>

#include <chrono>
#include <cstdio>
#include <thread>

#include "core/visibility/blind_controllers.h"
#include "tests/ui/headless_imgui.h"
#include "tests/ui/last_status.h"
#include "tests/ui/tabs/layout/inspector_fixture.h"
#include "ui/model/current_layout.h"
#include "ui/model/layout/layout_actions.h"
#include "ui/tabs/layout/coverage_panel.h"
#include "ui/tabs/layout/inspector_panel.h"
#include "ui/tabs/layout/layout_tab.h"
#include "ui/tabs/layout/optimiser_panel.h"
#include "ui/tabs/layout/scene_panel.h"

namespace lmc::ui {
namespace {

using testing::HeadlessImGui;

class RecordingRenderer final : public SceneRenderer {
 public:
  std::uintptr_t render(const SceneList& scene, const OrbitCamera&, int w, int h) override {
    last = scene;
    width = w;
    height = h;
    ++calls;
    return 0;
  }
  SceneList last;
  int width = 0, height = 0, calls = 0;
};

using SilentStatus = lmc::ui::testing::LastStatus;

// A small swarm for a quick search (the Optimiser panel's particles and iterations fields).
void set_swarm(LayoutState& state, int particles, int iterations) {
  PsoSettings p = state.pso();
  p.particles = particles;
  p.iterations = iterations;
  state.set_pso(p);
}

// A small pose set keeps every test fast (and under ASan).
void use_small_pose_set(LayoutState& s, int frames) {
  PoseSetChoice c;
  c.frames = frames;
  c.seed = 7;
  ASSERT_TRUE(set_pose_set_choice(s.upd_history(), c));
}

struct TabFixture : ::testing::Test {
  HeadlessImGui gui;
  SilentStatus status;
  RecordingRenderer* renderer = nullptr;
  std::unique_ptr<LayoutTab> tab;

  void SetUp() override {
    auto r = std::make_unique<RecordingRenderer>();
    renderer = r.get();
    tab = std::make_unique<LayoutTab>(status, std::move(r));
    tab->set_modals_enabled(false);
    use_small_pose_set(tab->state(), 40);
    tab->state().display.show_heatmap = false;
    tab->state().display.show_pyramids = false;  // a clear line of sight to the boxes
  }
  std::function<void()> body() {
    return [this] {
      tab->update(true);
      tab->draw();
    };
  }
  // Screen position of the centre of device i's box, from last frame's camera and image rect.
  ImVec2 device_on_screen(int i) {
    ScenePanel& sp = tab->scene_panel();
    const LayoutDevice& d = tab->state().layout().devices[static_cast<size_t>(i)];
    const Eigen::Vector3d c = d.to_world(Eigen::Vector3d(0, -2, 0));
    const auto p = tab->state().camera.project(c, sp.image_size().x, sp.image_size().y);
    EXPECT_TRUE(p.has_value());
    return ImVec2(sp.image_min().x + static_cast<float>(p->x()), sp.image_min().y + static_cast<float>(p->y()));
  }
};

TEST_F(TabFixture, SceneIsRenderedAtThePanelSizeWithEveryController) {
  gui.frames(3, body());
  EXPECT_GT(renderer->calls, 0);
  EXPECT_EQ(renderer->width, static_cast<int>(tab->scene_panel().image_size().x));
  EXPECT_GT(renderer->width, 500);
  EXPECT_EQ(renderer->last.count(ItemRole::kDevice), 4u);  // the paper's optimized layout, as processed
}

// A new user's first layout is one in which every controller sees the hand (the paper's table
// points LMC1 away from it; that preset stays in the Presets menu).
TEST_F(TabFixture, OpensOnALayoutInWhichEveryControllerSeesTheHand) {
  EXPECT_EQ(tab->state().layout().name, "paper-optimized-as-processed");
  EXPECT_EQ(tab->state().layout().device_count(), 4);
  EXPECT_TRUE(blind_controllers(tab->state().layout()).empty());
}

TEST_F(TabFixture, DraggingAControllerMovesItAndIsOneUndoStep) {
  tab->state().camera.set_named_view(NamedView::kTop);
  gui.frames(3, body());
  const LayoutDocument before = tab->state().history().head();
  const size_t commits = tab->state().history().undo_size();
  const ImVec2 from = device_on_screen(2);
  gui.drag(from, ImVec2(from.x + 80, from.y + 30), 8, body());

  const auto& hist = tab->state().history();
  EXPECT_EQ(hist.undo_size(), commits + 1) << "a drag is exactly one undo step";
  EXPECT_EQ(hist.undo_message(), "Move LMC3");
  EXPECT_EQ(tab->state().selected(), 2) << "pressing on a controller selects it";
  const DevicePose moved = hist.head().layout.devices[2].pose;
  const DevicePose was = before.layout.devices[2].pose;
  EXPECT_GT(moved.x_mm - was.x_mm, 20.0) << "dragged right in a top view: +x";
  EXPECT_EQ(moved.y_mm, was.y_mm);
  EXPECT_EQ(moved.rx_deg, was.rx_deg);
  EXPECT_EQ(moved.ry_deg, was.ry_deg);
  for (int i : {0, 1, 3})
    EXPECT_EQ(hist.head().layout.devices[static_cast<size_t>(i)], before.layout.devices[static_cast<size_t>(i)]);
  EXPECT_TRUE(tab->has_unsaved_changes());

  // Ctrl+Z restores the exact pose; Ctrl+Shift+Z brings the move back.
  gui.set_ctrl(true);
  gui.tap_key('Z', body());
  EXPECT_EQ(tab->state().history().head(), before);
  gui.set_shift(true);
  gui.tap_key('Z', body());
  gui.set_shift(false);
  gui.set_ctrl(false);
  EXPECT_EQ(tab->state().history().head().layout.devices[2].pose, moved);
  gui.set_ctrl(true);
  gui.tap_key('Z', body());
  gui.tap_key('Y', body());
  gui.set_ctrl(false);
  EXPECT_EQ(tab->state().history().head().layout.devices[2].pose, moved);
}

TEST_F(TabFixture, EscapeDuringADragPutsTheControllerBack) {
  tab->state().camera.set_named_view(NamedView::kTop);
  gui.frames(3, body());
  const LayoutDocument before = tab->state().history().head();
  const ImVec2 from = device_on_screen(3);
  gui.move_to(from.x, from.y);
  gui.frame(body());
  gui.set_button(0, true);
  gui.frame(body());
  gui.move_to(from.x + 60, from.y);
  gui.frame(body());
  EXPECT_NE(tab->state().layout().devices[3].pose, before.layout.devices[3].pose) << "the drag previews live";
  gui.tap_key(256, body());  // Escape
  gui.set_button(0, false);
  gui.frame(body());
  EXPECT_EQ(tab->state().history().head(), before);
  EXPECT_EQ(tab->state().doc(), before);
}

TEST_F(TabFixture, ClickingEmptySpaceClearsTheSelectionAndOrbitDragMovesOnlyTheCamera) {
  gui.frames(3, body());
  tab->state().select(0);
  const ScenePanel& sp = tab->scene_panel();
  const ImVec2 corner(sp.image_min().x + 15, sp.image_min().y + 15);
  const double yaw = tab->state().camera.yaw_deg();
  const size_t commits = tab->state().history().undo_size();
  gui.drag(corner, ImVec2(corner.x + 100, corner.y), 5, body());
  EXPECT_NE(tab->state().camera.yaw_deg(), yaw);
  EXPECT_EQ(tab->state().history().undo_size(), commits);
  EXPECT_EQ(tab->state().selected(), 0) << "a drag is not a click";
  gui.click(corner.x, corner.y, body());
  EXPECT_EQ(tab->state().selected(), -1);
}

// ---- optimiser panel on its own ----------------------------------------------------------------

struct OptimiserFixture : ::testing::Test {
  HeadlessImGui gui{900, 1000};
  SilentStatus status;
  std::shared_ptr<LayoutState> state = std::make_shared<LayoutState>(
      make_document(default_new_layout()), [this](const std::string& t, bool e) { status.set_status(t, e); });
  OptimiserPanel panel{state};

  void SetUp() override {
    use_small_pose_set(*state, 30);
    state->display.show_heatmap = false;
    state->update(0.0);
    state->poses.wait();
    state->update(0.0);
    ASSERT_TRUE(state->poses.current());
  }
  std::function<void()> body() {
    return [this] {
      state->update(1.0 / 60.0);
      panel.draw();
    };
  }
  void click(const std::string& anchor) {
    gui.frame(body());
    const auto c = panel.anchors().centre(anchor);
    ASSERT_TRUE(c.has_value()) << anchor << " is not on screen";
    gui.click(c->x, c->y, body());
  }
  void wait_until_idle() {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (state->optimiser().running() && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    gui.frame(body());
  }
};

TEST_F(OptimiserFixture, StartThenCancelLeavesTheLayoutUnchanged) {
  set_swarm(*state, 8, 100000);  // far more than can finish before Cancel
  const LayoutDocument before = state->history().head();
  const size_t commits = state->history().undo_size();
  click("start");
  EXPECT_TRUE(state->optimiser().running() || state->optimiser().state() == JobState::kCancelled);
  click("pso.cancel");
  wait_until_idle();
  EXPECT_EQ(state->optimiser().state(), JobState::kCancelled);
  EXPECT_EQ(status.last.rfind("Optimiser cancelled", 0), 0u) << status.last;
  EXPECT_EQ(state->history().head(), before);
  EXPECT_EQ(state->doc(), before);
  EXPECT_EQ(state->history().undo_size(), commits);
}

// A cancelled search's best so far is a real layout the panel offers to Apply: it is evaluated like
// a finished search's, so the comparison's robust rows and the status bar's M are its own, not zeros.
TEST_F(OptimiserFixture, ACancelledSearchsBestSoFarIsEvaluatedLikeAFinishedOne) {
  set_swarm(*state, 8, 100000);  // far more than can finish before Cancel
  click("start");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (state->optimiser().history().empty() && std::chrono::steady_clock::now() < deadline) gui.frame(body());
  ASSERT_FALSE(state->optimiser().history().empty()) << "the initial swarm was evaluated before Cancel";
  click("pso.cancel");
  wait_until_idle();
  ASSERT_EQ(state->optimiser().state(), JobState::kCancelled);
  const auto outcome = state->optimiser().outcome();
  ASSERT_TRUE(outcome);
  const PsoResult& r = outcome->pso;
  EXPECT_EQ(r.status, lmc::JobStatus::kCancelled);
  EXPECT_GT(r.best_cost, 0.0);
  EXPECT_EQ(r.best_terms.total, r.best_cost) << "the candidate's R is the search's own best cost";
  EXPECT_DOUBLE_EQ(r.best_terms.metric_m, outcome->candidate.all.metric) << "the M row and the robust terms agree";
  EXPECT_EQ(r.best_coverage.frames, 30);
  EXPECT_DOUBLE_EQ(r.best_coverage.metric, outcome->candidate.all.metric);
  char expected[160];
  std::snprintf(expected, sizeof expected, "Optimiser cancelled: best R = %.4g (M %.4g);", r.best_cost,
                outcome->candidate.all.metric);
  EXPECT_EQ(status.last.rfind(expected, 0), 0u) << status.last << "\nexpected it to start with: " << expected;
}

TEST_F(OptimiserFixture, ApplyReplacesTheLayoutInOneUndoableStep) {
  set_swarm(*state, 6, 3);
  const LayoutDocument before = state->history().head();
  const size_t commits = state->history().undo_size();
  click("start");
  wait_until_idle();
  ASSERT_EQ(state->optimiser().state(), JobState::kCompleted) << state->optimiser().error();
  ASSERT_TRUE(state->optimiser().outcome());
  EXPECT_FALSE(state->optimiser().history().empty()) << "the convergence plot has data";
  // The panel searches with the robust metric by default and says so.
  EXPECT_EQ(status.last.rfind("Optimiser finished: best R = ", 0), 0u) << status.last;
  EXPECT_EQ(state->optimiser().outcome()->pso.metric, PlacementMetricKind::kRobust);
  // The comparison's robust rows: the start layout's terms beside the candidate's, on the same
  // pose set with the same weights (the candidate's are the search's own cost, bit for bit).
  const auto& outcome = *state->optimiser().outcome();
  for (size_t d = 0; d < before.layout.devices.size(); ++d) {
    EXPECT_EQ(outcome.start_layout.devices[d].pose, before.layout.devices[d].pose);
  }
  EXPECT_GT(outcome.start_terms.total, 0.0);
  EXPECT_EQ(outcome.pso.best_terms.total, outcome.pso.best_cost);
  EXPECT_GT(outcome.start_terms.metric_m_inside_cut, 0.0);
  const Layout candidate = state->optimiser().outcome()->pso.best_layout;
  click("apply");
  EXPECT_EQ(state->history().undo_size(), commits + 1);
  EXPECT_EQ(state->history().undo_message(), "Apply optimised layout");
  for (size_t i = 0; i < candidate.devices.size(); ++i) {
    EXPECT_EQ(state->history().head().layout.devices[i].pose, candidate.devices[i].pose);
  }
  EXPECT_EQ(state->history().head().layout.name, "optimized-robust");
  EXPECT_NE(state->history().head().layout.description.find("robust metric"), std::string::npos);
  EXPECT_FALSE(state->optimiser().outcome()) << "applied candidates are not offered again";
  state->undo();
  EXPECT_EQ(state->history().head(), before);
}

TEST_F(OptimiserFixture, SeveralStartsKeepTheBestAndACurveEach) {
  set_swarm(*state, 6, 3);
  state->set_optimiser_starts(3);
  click("start");
  wait_until_idle();
  ASSERT_EQ(state->optimiser().state(), JobState::kCompleted) << state->optimiser().error();
  const auto outcome = state->optimiser().outcome();
  ASSERT_TRUE(outcome);
  ASSERT_EQ(outcome->start_costs.size(), 3u);
  ASSERT_EQ(state->optimiser().histories().size(), 3u);                          // one convergence curve per start
  for (const auto& h : state->optimiser().histories()) EXPECT_EQ(h.size(), 4u);  // iterations 0…3
  const double best = *std::min_element(outcome->start_costs.begin(), outcome->start_costs.end());
  EXPECT_DOUBLE_EQ(outcome->pso.best_cost, best);
  EXPECT_DOUBLE_EQ(outcome->start_costs[static_cast<size_t>(outcome->best_start)], best);
  EXPECT_NE(outcome->pso.best_layout.description.find("best of 3 starts"), std::string::npos)
      << outcome->pso.best_layout.description;
}

TEST_F(OptimiserFixture, LockedParametersStayPutInTheCandidate) {
  set_swarm(*state, 6, 2);
  for (int k = 0; k < kNumPoseParams; ++k) ASSERT_TRUE(set_device_lock(state->upd_history(), 0, k, true));
  click("start");
  wait_until_idle();
  ASSERT_TRUE(state->optimiser().outcome()) << state->optimiser().error();
  EXPECT_EQ(state->optimiser().outcome()->pso.best_layout.devices[0].pose,
            state->history().head().layout.devices[0].pose);
}

// ---- the Optimiser panel where a 1280 x 800 window puts it ------------------------------------------

// The shell's menu bar, tab strip and status bar leave a tab about 730 px of a 800 px window.
struct OptimiserAt1280x800 : ::testing::Test {
  HeadlessImGui gui{1280, 730};
  SilentStatus status;
  LayoutTab tab{status, std::make_unique<RecordingRenderer>()};

  void SetUp() override {
    tab.set_modals_enabled(false);
    use_small_pose_set(tab.state(), 40);
    tab.state().display.show_heatmap = false;
    set_swarm(tab.state(), 8, 100000);  // runs until cancelled
    tab.show_panel("optimiser");
    tab.optimiser_panel().open_settings_once();
    tab.state().update(0.0);
    tab.state().poses.wait();
  }
  std::function<void()> body() {
    return [this] {
      tab.update(true);
      tab.draw();
    };
  }
  const WidgetAnchors& anchors() { return tab.optimiser_panel().anchors(); }
  // Draws frames until `done` or 60 s.
  bool frames_until(const std::function<bool()>& done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!done() && std::chrono::steady_clock::now() < deadline) gui.frame(body());
    gui.frames(3, body());
    return done();
  }
};

TEST_F(OptimiserAt1280x800, SettingsRunningAndCancelledLinesAreNotCut) {
  gui.frames(3, body());
  EXPECT_TRUE(anchors().fits_across("starts")) << "the starts label is on the panel";
  EXPECT_TRUE(anchors().fits_across("movable-note")) << "(locks per parameter are in the Inspector) wraps";

  ASSERT_TRUE(tab.state().start_optimiser());
  ASSERT_TRUE(frames_until([&] { return !tab.state().optimiser().history().empty(); }));
  ASSERT_TRUE(tab.state().optimiser().running());
  EXPECT_TRUE(anchors().fully_visible("pso.cancel"));
  EXPECT_TRUE(anchors().fully_visible("pso.elapsed")) << "elapsed ... remaining ... under the progress bar";

  tab.state().cancel_optimiser();
  ASSERT_TRUE(frames_until([&] { return !tab.state().optimiser().running(); }));
  ASSERT_EQ(tab.state().optimiser().state(), JobState::kCancelled);
  EXPECT_TRUE(anchors().fully_visible("result")) << "Cancelled: best so far ... (… s)";
  EXPECT_TRUE(anchors().fully_visible("apply"));
  EXPECT_TRUE(anchors().fully_visible("discard"));
}

// ---- inspector and coverage panels on their own ---------------------------------------------------

using InspectorFixture = test::InspectorAt<700>;

TEST_F(InspectorFixture, AddSelectsTheNewControllerAndRemoveTakesItAwayEachOneUndoStep) {
  state->select(0);
  click("add");
  EXPECT_EQ(state->doc().device_count(), 5);
  EXPECT_EQ(state->selected(), 4);
  EXPECT_EQ(state->history().undo_message(), "Add LMC5");
  click("remove");
  EXPECT_EQ(state->doc().device_count(), 4);
  EXPECT_EQ(state->history().undo_size(), 2u);
  EXPECT_EQ(state->selected(), 3) << "the selection is pruned to an existing controller";
}

TEST_F(InspectorFixture, TheLockCheckboxLocksThatParameterOnly) {
  state->select(1);
  click("lock.0");
  EXPECT_TRUE(state->history().head().locks[1].locked[0]);
  EXPECT_FALSE(state->history().head().locks[0].locked[0]);
  EXPECT_EQ(state->history().undo_message(), "Lock LMC2 x");
}

TEST(CoveragePanel, DrawsTheTableOnceCoverageIsIn) {
  HeadlessImGui gui{700, 500};
  auto state = std::make_shared<LayoutState>(make_document(default_new_layout()));
  PoseSetChoice c;
  c.frames = 30;
  ASSERT_TRUE(set_pose_set_choice(state->upd_history(), c));
  state->display.show_heatmap = false;
  CoveragePanel panel{state};
  state->update(0.0);
  state->poses.wait();
  state->update(0.0);
  state->wait_for_coverage();
  gui.frames(2, [&] {
    state->update(1.0 / 60.0);
    panel.draw();
  });
  ASSERT_TRUE(state->coverage().latest());
  EXPECT_EQ(state->coverage().latest()->all.frames, 30);
  EXPECT_EQ(state->coverage().latest()->all.devices, 4);
}

// The workbench's one layout: the live rig follows what the Layout tab has committed,
// never a drag in progress (that would restart the rig every frame).
TEST(LayoutTabSharedLayout, PublishesTheCommittedLayoutNotADragInProgress) {
  HeadlessImGui gui;
  SilentStatus status;
  CurrentLayout shared;
  LayoutTab tab(status, std::make_unique<RecordingRenderer>(), &shared);
  EXPECT_EQ(shared.get(), tab.state().history().head().layout) << "published from the start";
  const auto published = shared.version();
  DevicePose p = tab.state().layout().devices[1].pose;
  p.x_mm += 50;
  ASSERT_TRUE(preview_device_pose(tab.state().upd_history(), 1, p).ok);
  gui.frames(2, [&] { tab.update(true); });
  EXPECT_EQ(shared.version(), published);
  ASSERT_TRUE(commit_device_pose(tab.state().upd_history(), 1, "Move"));
  gui.frames(2, [&] { tab.update(true); });
  EXPECT_EQ(shared.version(), published + 1);
  EXPECT_EQ(shared.get().devices[1].pose.x_mm, p.x_mm);
}

}  // namespace
}  // namespace lmc::ui
