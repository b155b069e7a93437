#include "ui/model/layout/layout_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

#include "core/common/error.h"
#include "core/io/layout_json.h"

namespace lmc::ui {

LayoutState::LayoutState(LayoutDocument initial, StatusFn status)
    : document_(std::move(initial)), status_(std::move(status)) {
  saved_head_id_ = document_.head_id();
  // Leave one core to the UI thread; the result does not depend on the thread count.
  pso_.threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1);
  // The Optimiser panel searches with the robust metric unless the user picks the study's.
  pso_.metric = PlacementMetricKind::kRobust;
}

bool LayoutState::report(const ActionResult& r, const std::string& what) {
  if (!r) {
    set_status(what + ": " + r.error, true);
    return false;
  }
  prune_selection();
  return true;
}

void LayoutState::undo() {
  if (!document_.can_undo()) return;
  const std::string msg = document_.undo_message();
  document_.undo();
  prune_selection();
  set_status("Undid " + msg);
}

void LayoutState::redo() {
  if (!document_.can_redo()) return;
  const std::string msg = document_.redo_message();
  document_.redo();
  prune_selection();
  set_status("Redid " + msg);
}

std::string LayoutState::title() const {
  std::string t = file_path_
                      ? file_path_->filename().string()
                      : (layout().name.empty() ? std::string("untitled layout") : layout().name + " (not saved)");
  if (unsaved()) t += " *";  // the usual unsaved-changes mark
  return t;
}

namespace {
// lmc::Error's what() already starts with "file: at /json/path: " (its constructor formats the
// location in); formatting the location again printed it twice.
std::string error_text(const std::exception& e) {
  return e.what();
}
}  // namespace

std::string LayoutState::open_file(const std::filesystem::path& path) {
  try {
    const Layout l = load_layout(path);
    if (ActionResult r = replace_layout(document_, l, "Open " + path.filename().string()); !r) return r.error;
    file_path_ = path;
    saved_head_id_ = document_.head_id();
    prune_selection();
    set_status("Opened " + path.string());
    return {};
  } catch (const std::exception& e) {
    const std::string msg = error_text(e);
    set_status("Cannot open layout: " + msg, true);
    return msg;
  }
}

std::string LayoutState::save_to(const std::filesystem::path& path) {
  try {
    document_.rollback();  // never save a half-finished drag
    save_layout(document_.head().layout, path);
    file_path_ = path;
    saved_head_id_ = document_.head_id();
    set_status("Saved " + path.string());
    return {};
  } catch (const std::exception& e) {
    const std::string msg = error_text(e);
    set_status("Cannot save layout: " + msg, true);
    return msg;
  }
}

std::string LayoutState::load_preset(const std::string& name) {
  try {
    const Layout l = load_layout_or_preset(name);
    if (ActionResult r = replace_layout(document_, l, "Load preset " + name); !r) return r.error;
    // A preset is not a file of the user's: "Save" asks where to put it.
    file_path_.reset();
    prune_selection();
    set_status("Loaded preset " + name);
    return {};
  } catch (const std::exception& e) {
    const std::string msg = error_text(e);
    set_status("Cannot load preset: " + msg, true);
    return msg;
  }
}

void LayoutState::new_layout() {
  replace_layout(document_, default_new_layout(), "New layout");
  file_path_.reset();
  prune_selection();
}

void LayoutState::select(int device) {
  selected_ = (device >= 0 && device < doc().device_count()) ? device : -1;
}

void LayoutState::prune_selection() {
  if (selected_ >= doc().device_count()) selected_ = doc().device_count() - 1;
  if (hovered_ >= doc().device_count()) hovered_ = -1;
}

const HandFrame* LayoutState::current_hand() const {
  const PoseSetPtr p = poses.current();
  if (!p || p->size() == 0) return nullptr;
  const int j = std::clamp(timeline.frame, 0, p->size() - 1);
  return &p->set.frames[static_cast<size_t>(j)];
}

ColourRange LayoutState::heatmap_range() const {
  if (display.heatmap_fixed_range) return {0.0, 1.0};
  const HeatmapGridPtr g = heatmap_.latest();
  if (!g || g->data_max <= g->data_min) return {0.0, 1.0};
  return {g->data_min, g->data_max};
}

void LayoutState::refresh_timeline_frames() {
  const PoseSetPtr p = poses.current();
  const std::uint64_t v = p ? p->version : 0;
  if (v == timeline_version_ && timeline_filters_[0] == timeline.orientation_filter &&
      timeline_filters_[1] == timeline.motion_filter) {
    return;
  }
  timeline_version_ = v;
  timeline_filters_[0] = timeline.orientation_filter;
  timeline_filters_[1] = timeline.motion_filter;
  timeline_frames_.clear();
  if (!p) return;
  for (int j = 0; j < p->size(); ++j) {
    const PoseLabel& l = p->set.labels[static_cast<size_t>(j)];
    if (timeline.orientation_filter >= 0 && static_cast<int>(l.orientation) != timeline.orientation_filter) continue;
    if (timeline.motion_filter >= 0 && static_cast<int>(l.motion) != timeline.motion_filter) continue;
    timeline_frames_.push_back(j);
  }
  if (!timeline_frames_.empty() &&
      !std::binary_search(timeline_frames_.begin(), timeline_frames_.end(), timeline.frame)) {
    timeline.frame = timeline_frames_.front();
  }
}

void LayoutState::update(double dt_seconds, bool on_screen) {
  poses.request(doc().pose_set);
  poses.poll();
  report_recorded_pose_set();
  coverage_.poll();
  heatmap_.poll();
  optimiser_.poll();
  report_optimiser_end();
  prune_selection();
  refresh_timeline_frames();

  // Playback walks the filtered frames.
  if (timeline.playing && !timeline_frames_.empty()) {
    timeline.play_accumulator_s += std::max(0.0, dt_seconds);
    const double step = 1.0 / std::max(timeline.frames_per_second, 0.1);
    int advance = 0;
    while (timeline.play_accumulator_s >= step && advance < 1000) {
      timeline.play_accumulator_s -= step;
      ++advance;
    }
    if (advance > 0) {
      auto it = std::lower_bound(timeline_frames_.begin(), timeline_frames_.end(), timeline.frame);
      size_t pos = static_cast<size_t>(it - timeline_frames_.begin());
      pos = (pos + static_cast<size_t>(advance)) % timeline_frames_.size();
      timeline.frame = timeline_frames_[pos];
    }
  }

  const PoseSetPtr p = poses.current();
  if (p) {
    coverage_.request(layout(), p);
    const int j = std::clamp(timeline.frame, 0, std::max(0, p->size() - 1));
    if (p->size() > 0) {
      frame_visibility_ =
          explain_frame(layout(), p->prepared[static_cast<size_t>(j)], display.show_rays ? selected_ : -1);
    }
    if (display.show_heatmap && selected_ >= 0) {
      HeatmapRequest req;
      req.layout = layout();
      req.device = selected_;
      req.finger = display.heatmap_finger;
      req.mode = display.heatmap_mode;
      req.cells = display.heatmap_cells;
      req.half_extent_mm = display.heatmap_half_extent_mm;
      req.poses = p;
      if (on_screen) {
        heatmap_.request(req);
      } else {
        heatmap_.pause();
      }
    } else {
      heatmap_.clear();
    }
  } else {
    frame_visibility_ = {};
  }
}

bool LayoutState::start_optimiser() {
  document_.rollback();
  if (!optimiser_.start(document_.head(), poses.current(), pso_, optimiser_starts_)) {
    set_status("Cannot start the optimiser: " + optimiser_.error(), true);
    return false;
  }
  set_status("Optimiser started");
  return true;
}

void LayoutState::report_optimiser_end() {
  const JobState now = optimiser_.state();
  if (now == last_optimiser_state_) return;
  last_optimiser_state_ = now;
  if (!job_finished(now)) return;
  if (now == JobState::kFailed) {
    set_status("Optimiser failed: " + optimiser_.error(), true);
    return;
  }
  const auto outcome = optimiser_.outcome();
  if (!outcome) {
    set_status(now == JobState::kCancelled ? "Optimiser cancelled before its first iteration" : "Optimiser finished");
    return;
  }
  char buf[200];
  const PsoResult& r = outcome->pso;
  if (r.metric == PlacementMetricKind::kStudy) {
    std::snprintf(buf, sizeof buf, "Optimiser %s: best M = %.4g; Apply or Discard it in the Optimiser panel",
                  now == JobState::kCancelled ? "cancelled" : "finished", r.best_cost);
  } else {
    std::snprintf(buf, sizeof buf, "Optimiser %s: best R = %.4g (M %.4g); Apply or Discard it in the Optimiser panel",
                  now == JobState::kCancelled ? "cancelled" : "finished", r.best_cost, r.best_terms.metric_m);
  }
  set_status(buf);
}

bool LayoutState::apply_optimised() {
  const auto outcome = optimiser_.outcome();
  if (!outcome) return false;
  if (!report(apply_layout(document_, outcome->pso.best_layout), "Apply optimised layout")) return false;
  optimiser_.discard();
  set_status("Applied the optimised layout (Ctrl+Z to undo)");
  return true;
}

void LayoutState::start_report(const std::filesystem::path& dir) {
  if (const PoseSetPtr p = poses.current()) report_job_.start(layout(), p, dir);
}

bool LayoutState::busy() const {
  return poses.loading() || !poses.current() || coverage_.busy() || optimiser_.running() ||
         (display.show_heatmap && selected_ >= 0 && !heatmap_.complete() && heatmap_.error().empty());
}

bool LayoutState::use_recorded_pose_set(std::vector<std::string> recordings, std::string source,
                                        std::string trials_glob, int every) {
  PoseSetChoice choice = doc().pose_set;
  choice.source = PoseSetChoice::Source::kRecordings;
  choice.recordings = std::move(recordings);
  choice.recorded_source = std::move(source);
  choice.trials_glob = std::move(trials_glob);
  choice.every = every;
  return report(set_pose_set_choice(document_, choice), "Pose set");
}

void LayoutState::report_recorded_pose_set() {
  const PoseSetPtr p = poses.current();
  if (!p || p->version == reported_pose_set_version_) return;
  reported_pose_set_version_ = p->version;
  if (p->choice.source != PoseSetChoice::Source::kRecordings) return;
  set_status("Pose set: " + std::to_string(p->size()) + " recorded frames (" + p->set.description + ")" +
                 (p->left_out.empty() ? "" : ", " + std::to_string(p->left_out.size()) + " trials left out"),
             false);
}

void LayoutState::cancel_pose_set_load() {
  if (!poses.loading()) return;
  poses.cancel();
  if (const PoseSetPtr p = poses.current()) report(set_pose_set_choice(document_, p->choice), "Pose set");
}

}  // namespace lmc::ui
