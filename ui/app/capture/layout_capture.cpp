// The Layout tab's pictures: the start layout (or LMC_LAYOUT_PRESET) with the index finger's
// heatmap, pyramids and rays, then "layout-mixed-rig" (the same layout as two Leap Motion
// Controllers and two LMC2s, the first LMC2 selected with its model in the Inspector).
// Switches: LMC_LAYOUT_PANEL=inspector|heatmap|optimiser|optimiser-settings (the Optimiser with its
// settings and term weights open)|optimiser-compare (scrolled to Current vs candidate) picks the
// right-hand panel; LMC_LAYOUT_VIEW=top|front|side; LMC_LAYOUT_PLAIN=1 (controllers, hand and
// coverage only); LMC_LAYOUT_HEATMAP_CELLS=N; LMC_LAYOUT_OPTIMISE=N runs an N-iteration search
// first (LMC_LAYOUT_STARTS=N starts, LMC_LAYOUT_CANCEL_AFTER=S cancels it S seconds in);
// LMC_LAYOUT_FRAME_STATS=N times N frames of a scripted drag (printed on stderr at the end).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "ui/app/capture/tab_capture.h"
#include "ui/tabs/layout/inspector_panel.h"
#include "ui/tabs/layout/layout_tab.h"
#include "ui/tabs/layout/optimiser_panel.h"
#include "ui/tabs/layout/scene_panel.h"

namespace lmc::ui {
namespace {

int env_int(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr ? std::atoi(v) : 0;
}

// LMC_LAYOUT_FRAME_STATS=N: a scripted drag of the selected controller for N frames, timing each
// frame of the shell (every tab's update and this tab's draw, GL submission included).
class FrameStats {
 public:
  FrameStats(LayoutState& state, int frames) : state_(state), wanted_(frames) {
    start_pose_ = state_.layout().devices[1].pose;
  }
  bool running() const { return frame_ < wanted_; }

  void before_frame() {
    frame_start_ = std::chrono::steady_clock::now();
    drag_step();
  }
  void after_frame() {
    if (frame_ == 0 || frame_ > wanted_) return;
    if (const auto snap = state_.coverage().latest(); snap && snap.get() != last_snapshot_) {
      last_snapshot_ = snap.get();
      ++coverage_updates_;
    }
    if (frame_ms_.size() < static_cast<size_t>(wanted_))
      frame_ms_.push_back(ms_since(std::chrono::steady_clock::now()));
  }
  void report() const;

 private:
  double ms_since(std::chrono::steady_clock::time_point now) const {
    return std::chrono::duration<double, std::milli>(now - frame_start_).count();
  }
  void drag_step() {
    LayoutState& s = state_;
    if (frame_ >= wanted_ || s.selected() < 0 || !s.poses.current()) return;
    // Start once the heatmap and coverage have settled, so the figure is "dragging with live
    // coverage", not "dragging while the first heatmap sweep is still running".
    if (frame_ == 0 && s.busy()) return;
    // A slow circle of 80 mm around the start position, as a hand on the mouse would do.
    const double t = frame_ * 0.05;
    DevicePose p = start_pose_;
    p.x_mm += 80.0 * std::sin(t);
    p.z_mm += 80.0 * (1.0 - std::cos(t));
    preview_device_pose(s.upd_history(), s.selected(), p);
    if (++frame_ == wanted_) commit_device_pose(s.upd_history(), s.selected(), "Move");
  }

  LayoutState& state_;
  int wanted_ = 0;
  int frame_ = 0;
  DevicePose start_pose_;
  std::vector<double> frame_ms_;
  std::chrono::steady_clock::time_point frame_start_{};
  int coverage_updates_ = 0;
  const void* last_snapshot_ = nullptr;
};

void FrameStats::report() const {
  if (frame_ms_.empty()) return;
  std::vector<double> v = frame_ms_;
  std::sort(v.begin(), v.end());
  double sum = 0;
  for (double x : v) sum += x;
  const auto pct = [&](double q) {
    return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
  };
  const PoseSetPtr p = state_.poses.current();
  std::fprintf(
      stderr,
      "layout tab frame CPU (every tab's update + the layout tab's draw incl. scene rendering), %zu frames "
      "while dragging %s: mean %.2f ms, median %.2f ms, p95 %.2f ms, max %.2f ms; %d controllers, %d-frame "
      "pose set, %d coverage updates during the drag\n",
      v.size(),
      state_.selected() >= 0 ? state_.layout().devices[static_cast<size_t>(state_.selected())].slot.c_str() : "-",
      sum / static_cast<double>(v.size()), pct(0.5), pct(0.95), v.back(), state_.layout().device_count(),
      p ? p->size() : 0, coverage_updates_);
}

class LayoutCapture final : public TabCapture {
 public:
  explicit LayoutCapture(LayoutTab& tab) : tab_(tab) {}

  int prepare() override {
    LayoutState& s = tab_.state();
    // What a new user sees first, or LMC_LAYOUT_PRESET=NAME (the Devices capture follows it).
    const char* preset = std::getenv("LMC_LAYOUT_PRESET");
    s.load_preset(preset != nullptr && *preset != '\0' ? preset : LayoutTab::kStartLayout);
    s.select(1);
    s.display.show_heatmap = true;
    s.display.heatmap_finger = 1;  // index: the finger the study's index-flexion trials move
    s.display.show_pyramids = true;
    s.display.show_rays = true;
    tab_.scene_panel().frame_all();
    if (const char* view = std::getenv("LMC_LAYOUT_PLAIN"); view != nullptr && view[0] == '1') {
      // Controllers, hand and coverage only: for comparing frame times without the heavy overlays.
      s.display.show_pyramids = false;
      s.display.show_heatmap = false;
      s.display.show_rays = false;
    }
    // A coarser heatmap grid: the smoke test under ASan uses 24, as the 48×48 sweep did not
    // finish within the capture's 20 s there and went on using a core beside the other tests.
    if (const int cells = env_int("LMC_LAYOUT_HEATMAP_CELLS"); cells > 0) {
      s.display.heatmap_cells = std::clamp(cells, 8, 96);  // the Heatmap panel's slider range
    }
    if (const char* view = std::getenv("LMC_LAYOUT_VIEW")) {  // top, front or side (default: 3D)
      const std::string v = view;
      if (v == "top") s.camera.set_named_view(NamedView::kTop);
      if (v == "front") s.camera.set_named_view(NamedView::kFront);
      if (v == "side") s.camera.set_named_view(NamedView::kSide);
    }
    if (const char* panel = std::getenv("LMC_LAYOUT_PANEL")) show_panel(panel);
    if (const int iterations = env_int("LMC_LAYOUT_OPTIMISE"); iterations > 0) start_search(iterations);
    if (const int frames = env_int("LMC_LAYOUT_FRAME_STATS"); frames > 0) stats_.emplace(s, frames);
    return 4;
  }

  // Care: the capture gives a tab at most 20 s; use a few hundred frames for the statistics.
  bool busy() const override { return tab_.state().busy() || (stats_ && stats_->running()); }

  std::vector<std::string> extra_captures() const override { return {"layout-mixed-rig"}; }

  void prepare_extra(const std::string& name) override {
    if (name != "layout-mixed-rig") return;
    LayoutState& s = tab_.state();
    const char* models[] = {"lmc", "lmc", "lmc2", "lmc2"};
    for (int i = 0; i < s.layout().device_count() && i < 4; ++i) {
      const size_t steps = s.history().undo_size();
      s.report(set_device_model(s.upd_history(), i, models[i]), "Model");
      mixed_rig_steps_ += static_cast<int>(s.history().undo_size() - steps);
    }
    s.select(2);
    tab_.show_panel("inspector");
    tab_.inspector_panel().show_model_once();
  }

  void before_frame(bool shown) override {
    if (stats_) stats_->before_frame();
    if (cancel_at_ && std::chrono::steady_clock::now() >= *cancel_at_) {
      cancel_at_.reset();
      tab_.state().cancel_optimiser();
    }
    // The mixed rig's model changes are taken back once another tab is shown, so the tabs
    // captured after it (Devices) see the layout they always saw.
    if (!shown) {
      for (; mixed_rig_steps_ > 0; --mixed_rig_steps_) tab_.state().undo();
    }
  }
  void after_frame(bool /*shown*/) override {
    if (stats_) stats_->after_frame();
  }
  void finish() override {
    if (stats_) stats_->report();
  }

 private:
  void show_panel(std::string panel) {
    // "optimiser-settings": the Optimiser panel with its settings and term weights open.
    if (panel == "optimiser-settings") {
      panel = "optimiser";
      tab_.optimiser_panel().open_settings_once();
    }
    // "optimiser-compare": the Optimiser panel scrolled to the robust rows of Current vs candidate.
    if (panel == "optimiser-compare") {
      panel = "optimiser";
      tab_.optimiser_panel().show_comparison_once();
    }
    tab_.show_panel(panel);
  }

  void start_search(int iterations) {
    LayoutState& s = tab_.state();
    PsoSettings pso = s.pso();
    pso.iterations = iterations;
    s.set_pso(pso);
    // LMC_LAYOUT_STARTS=N: a multi-start run, so the picture shows a convergence curve per start.
    if (const int starts = env_int("LMC_LAYOUT_STARTS"); starts > 0) s.set_optimiser_starts(starts);
    s.update(0.0);
    s.poses.wait();
    s.update(0.0);
    s.start_optimiser();
    // LMC_LAYOUT_CANCEL_AFTER=S: the picture shows a cancelled search's best so far.
    if (const char* after = std::getenv("LMC_LAYOUT_CANCEL_AFTER"); after != nullptr && std::atof(after) > 0) {
      cancel_at_ = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                          std::chrono::duration<double>(std::atof(after)));
    }
  }

  LayoutTab& tab_;
  std::optional<FrameStats> stats_;
  std::optional<std::chrono::steady_clock::time_point> cancel_at_;
  int mixed_rig_steps_ = 0;  // undo steps "layout-mixed-rig" added, taken back when another tab is shown
};

}  // namespace

std::unique_ptr<TabCapture> make_layout_capture(LayoutTab& tab) {
  return std::make_unique<LayoutCapture>(tab);
}

}  // namespace lmc::ui
