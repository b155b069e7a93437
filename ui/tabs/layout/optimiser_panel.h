#pragma once
// The placement search from the workbench: pose set (Monte Carlo frames + seed, a file or recipe, or
// the hands of recorded trials, read by a worker with progress and Cancel), PSO
// settings with the study's defaults, which controllers may move and within which bounds; Start
// runs it in the background with progress, ETA, a live convergence plot (log scale) and Cancel.
// The best layout is drawn as ghost controllers; Apply replaces the layout (one undo step); the
// comparison table shows current vs candidate.
#include <memory>

#include "ui/model/layout/layout_state.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/series_plot.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class OptimiserPanel : public Panel {
 public:
  explicit OptimiserPanel(std::shared_ptr<LayoutState> state);
  void draw();
  // Start, pso.cancel, pso.elapsed, Apply, Discard, the result line and a few labels as last drawn
  // (for headless tests).
  const WidgetAnchors& anchors() const { return anchors_; }
  // For --capture: the next draw opens Search settings and the term weights.
  void open_settings_once() { open_settings_once_ = true; }
  // The pose set changed from outside (Review's "Design a layout for these trials"): the next draw
  // shows the document's choice, not the one being edited.
  void show_pose_set_once() { choice_synced_ = false; }
  // For --capture: once the search has a result, scroll to the end of Current vs candidate.
  void show_comparison_once() { show_comparison_once_ = true; }

 private:
  void draw_pose_set();
  void draw_pose_set_status();
  void draw_recordings_choice();
  void draw_settings();
  void draw_metric(PsoSettings& p);  // the metric and, for the robust one, its term weights
  void draw_swarm(PsoSettings& p);   // particles, iterations, starts, seed and the swarm's constants
  void draw_movable();               // which controllers the search may move
  void draw_bounds();                // the search range of each pose parameter
  void draw_run();                   // the footer: Start or progress, then the result with Apply / Discard
  void draw_convergence();
  void draw_comparison();

  std::shared_ptr<LayoutState> state_;
  PoseSetChoice edit_choice_;
  bool choice_synced_ = false;
  char file_buf_[512] = {};
  FileBrowser browser_{"Choose a pose-set file", ".tsv"};
  // From recordings: the folder of the chosen trial file (a processed trial's .fused.txt, or an
  // LMC recording for one controller's or Vicon's hands).
  char recordings_buf_[1024] = {};
  char trials_buf_[128] = {};
  FileBrowser recordings_browser_{"Choose a trial (its folder is read)", ".txt"};
  WidgetAnchors anchors_;
  SeriesPlot convergence_;             // best cost per iteration (ui/widgets/series_plot.h)
  std::vector<double> convergence_x_;  // 0, 1, 2, … (the iterations)
  bool open_settings_once_ = false;
  bool show_comparison_once_ = false;
  float footer_h_ = 0;  // height of the footer (draw_run) as last drawn
};

}  // namespace lmc::ui
