#pragma once
// Everything the Layout tab's panels share (docs/architecture.md): the undoable document and its file,
// selection and hover, the camera, the timeline, display settings, the derived-result caches and
// the job handles. Panels read it through const accessors and change it through actions (ui/model/
// layout_actions.h) or job controls. No ImGui and no GL here, so the tab's logic is testable with
// plain gtest; update() is the frame's update step (poll jobs, refresh caches) and never blocks.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/optimise/pso.h"
#include "ui/model/layout/coverage_cache.h"
#include "ui/model/layout/frame_visibility.h"
#include "ui/model/layout/heatmap_cache.h"
#include "ui/model/layout/layout_actions.h"
#include "ui/model/layout/layout_report_job.h"
#include "ui/model/layout/optimiser_job.h"
#include "ui/model/layout/pose_set_store.h"
#include "ui/scene/colour_maps.h"
#include "ui/scene/drag_controller.h"
#include "ui/scene/orbit_camera.h"

namespace lmc::ui {

struct TimelineState {
  int frame = 0;  // index into the pose set (not into the filtered list)
  bool playing = false;
  double frames_per_second = 30;
  int orientation_filter = -1;  // −1 any, else HandOrientation
  int motion_filter = -1;       // −1 any, else HandMotion
  double play_accumulator_s = 0;
};

struct DisplaySettings {
  bool show_pyramids = true;
  bool show_rays = false;
  bool show_heatmap = true;
  bool show_ghost = true;
  int heatmap_finger = -1;  // −1 all five
  HeatmapMode heatmap_mode = HeatmapMode::kShareVisible;
  int heatmap_cells = 48;
  double heatmap_half_extent_mm = 400;
  bool heatmap_fixed_range = true;  // 0…100 % (comparable between fingers) or the data's range
  bool show_search_box = false;     // the Optimiser panel is open: draw its x/z bounds on the table
};

class LayoutState {
 public:
  using StatusFn = std::function<void(const std::string&, bool is_error)>;
  explicit LayoutState(LayoutDocument initial, StatusFn status = {});

  // ---- document --------------------------------------------------------------------------------
  const UndoableLayoutDocument& history() const { return document_; }
  UndoableLayoutDocument& upd_history() { return document_; }
  // What is on screen: the scratch copy, so a drag in progress shows live.
  const LayoutDocument& doc() const { return document_.scratch(); }
  const Layout& layout() const { return document_.scratch().layout; }
  // Reports an action's outcome in the status line; returns ok.
  bool report(const ActionResult& r, const std::string& what);
  void undo();
  void redo();

  // ---- file -----------------------------------------------------------------------------------
  const std::optional<std::filesystem::path>& file_path() const { return file_path_; }
  bool unsaved() const { return document_.head_id() != saved_head_id_; }
  std::string title() const;  // "paper-optimized.json •" / "untitled •"
  // Each returns an empty string on success, else the error (with file and JSON path) to show.
  std::string open_file(const std::filesystem::path& path);
  std::string save_to(const std::filesystem::path& path);
  std::string load_preset(const std::string& name);  // "paper-initial", "paper-optimized"
  void new_layout();

  // ---- selection ------------------------------------------------------------------------------
  int selected() const { return selected_; }  // −1: none
  // The controller under the pointer (−1: none) and which of its handles; the handle being dragged.
  int hovered() const { return hovered_; }
  HandleKind hovered_handle() const { return hovered_handle_; }
  HandleKind active_handle() const { return active_handle_; }
  void set_hover(int device, HandleKind handle) {
    hovered_ = device;
    hovered_handle_ = handle;
  }
  void set_active_handle(HandleKind handle) { active_handle_ = handle; }
  void select(int device);
  // Drops selection and hover that no longer exist (after undo, remove, open).
  void prune_selection();

  // ---- view -----------------------------------------------------------------------------------
  OrbitCamera camera;
  TimelineState timeline;
  DisplaySettings display;

  // ---- the optimiser's settings ------------------------------------------------------------------
  const PsoSettings& pso() const { return pso_; }
  void set_pso(const PsoSettings& settings) { pso_ = settings; }
  // Swarms from seeds pso().seed, pso().seed + 1, …; the best is kept.
  int optimiser_starts() const { return optimiser_starts_; }
  void set_optimiser_starts(int starts) { optimiser_starts_ = std::clamp(starts, 1, 8); }

  // ---- derived data ----------------------------------------------------------------------------
  PoseSetStore poses;
  const CoverageCache& coverage() const { return coverage_; }
  const HeatmapCache& heatmap() const { return heatmap_; }
  const OptimiserJob& optimiser() const { return optimiser_; }
  // "Report...": lmc evaluate --report for the edited layout and the pose set, into `dir`.
  const LayoutReportJob& report_job() const { return report_job_; }
  void start_report(const std::filesystem::path& dir);
  // Blocks until the coverage of the current document is in (tests).
  void wait_for_coverage() { coverage_.wait(); }
  const FrameVisibility& frame_visibility() const { return frame_visibility_; }
  const std::vector<int>& timeline_frames() const { return timeline_frames_; }  // after filters
  // The hand on screen (world frame), or null while the pose set loads.
  const HandFrame* current_hand() const;
  ColourRange heatmap_range() const;

  // Update step: poll jobs, advance the timeline by dt, refresh caches for the current document.
  // `on_screen` false (another tab is shown): no heatmap sweep, whose full pass takes a core for
  // seconds that a recording beside it needs; the coverage and a running optimiser go on.
  void update(double dt_seconds, bool on_screen = true);
  // Start / cancel / apply the optimiser (job controls).
  bool start_optimiser();
  void cancel_optimiser() { optimiser_.cancel(); }
  // Designs on recorded hands: the pose set becomes these trials' (Review's "Design a layout for
  // these trials", the Optimiser panel's "From recordings"); one undo step. False with the reason
  // in the status line when there is nothing to read.
  bool use_recorded_pose_set(std::vector<std::string> recordings, std::string source = "fused",
                             std::string trials_glob = {}, int every = 1);
  // Stops loading a pose set and goes back to the set loaded before (an undo step of its own).
  void cancel_pose_set_load();
  bool apply_optimised();
  void discard_optimised() { optimiser_.discard(); }
  // True while background work that a screenshot should wait for is running.
  bool busy() const;

  void set_status(const std::string& text, bool is_error = false) const {
    if (status_) status_(text, is_error);
  }

 private:
  void refresh_timeline_frames();
  // Tells the status bar once when a search ends, whichever panel is showing.
  void report_optimiser_end();
  // Tells the status bar once when a recorded pose set is in (how many frames, from where).
  void report_recorded_pose_set();

  UndoableLayoutDocument document_;
  int selected_ = -1;
  int hovered_ = -1;
  HandleKind hovered_handle_ = HandleKind::kNone;
  HandleKind active_handle_ = HandleKind::kNone;
  PsoSettings pso_;
  int optimiser_starts_ = 1;
  CoverageCache coverage_;
  HeatmapCache heatmap_;
  OptimiserJob optimiser_;
  LayoutReportJob report_job_;
  JobState last_optimiser_state_ = JobState::kIdle;
  std::uint64_t reported_pose_set_version_ = 0;
  std::uint64_t saved_head_id_ = 0;
  std::optional<std::filesystem::path> file_path_;
  StatusFn status_;
  FrameVisibility frame_visibility_;
  std::vector<int> timeline_frames_;
  std::uint64_t timeline_version_ = 0;
  int timeline_filters_[2] = {-2, -2};
};

}  // namespace lmc::ui
