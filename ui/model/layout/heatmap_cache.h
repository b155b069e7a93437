#pragma once
// Per-finger table heatmaps for the selected controller: for each cell of a grid on
// the table, the share of pose-set frames in which the chosen finger would be visible if the
// controller's origin stood above that cell (same height and orientation — an approximation:
// a real move on the table might also change the tilt a lab would choose), or, in the second
// mode, the share of frames it would *add* (visible to it and seen by no other controller).
//
// Computed on a worker thread, coarse to fine (quarter, half, then full resolution), each pass
// published as a complete immutable grid so the scene always has something correct to draw. A
// change of anything the grid depends on abandons the running sweep (it stops at its next row)
// and starts a new one; the frame never waits for the old one. Moving the swept controller itself
// does not restart the sweep: its x and z are what the sweep varies.
#include <cstdint>
#include <memory>
#include <stop_token>

#include "core/layout/layout.h"
#include "ui/model/jobs/background_job.h"
#include "ui/model/layout/pose_set_store.h"
#include "ui/scene/heatmap_grid.h"

namespace lmc::ui {

struct HeatmapRequest {
  Layout layout;
  int device = 0;
  int finger = -1;  // 0 thumb … 4 pinky, −1 all five
  HeatmapMode mode = HeatmapMode::kShareVisible;
  int cells = 48;  // per side
  double half_extent_mm = 400;
  PoseSetPtr poses;

  // Equal when the sweep would give the same grid (the swept device's x and z are ignored).
  bool same_sweep(const HeatmapRequest& o) const;
};

using HeatmapGridPtr = std::shared_ptr<const HeatmapGrid>;

// One pass of the sweep at `cells` × `cells`, synchronously; nullptr when stopped.
HeatmapGridPtr sweep_heatmap(const HeatmapRequest& request, int cells, std::stop_token stop = {},
                             JobChannel<HeatmapGridPtr>* channel = nullptr, long long done_before = 0,
                             long long total = 0);

class HeatmapCache {
 public:
  void request(const HeatmapRequest& request);
  void clear();  // heatmap switched off: stop and forget
  // Off screen: stop a sweep in progress but keep the last grid; the next request starts afresh.
  void pause();
  void poll();  // update step: pick up published passes, reap abandoned workers

  HeatmapGridPtr latest() const { return latest_; }
  bool computing() const { return job_.running(); }
  double fraction() const { return job_.fraction(); }
  std::string stage() const { return job_.stage(); }
  const std::string& error() const { return error_; }
  // True once the full-resolution pass for the current request is in.
  bool complete() const { return latest_ && latest_->fine && latest_->key == key_; }

 private:
  JobGraveyard graveyard_;
  HeatmapRequest current_;
  bool has_request_ = false;
  std::uint64_t key_ = 0;
  HeatmapGridPtr latest_;
  std::string error_;
  // The graveyard is declared first so it is destroyed last: abandoned workers are joined after
  // the current job.
  BackgroundJob<int, HeatmapGridPtr> job_;
};

}  // namespace lmc::ui
