#pragma once
// The pose set the Layout tab shows and scores, loaded (Monte Carlo generation or a file) and
// prepared for the visibility kernels on a worker thread. A loaded set is immutable and carries a
// version id, so caches compare ids instead of 2,000 frames (docs/architecture.md).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/hand/pose_set.h"
#include "core/visibility/frame_prep.h"
#include "ui/model/jobs/background_job.h"
#include "ui/model/layout/layout_document.h"

namespace lmc::ui {

struct LoadedPoseSet {
  std::uint64_t version = 0;
  PoseSetChoice choice;
  PoseSet set;
  std::vector<PreparedFrame> prepared;
  std::vector<int> horizontal, vertical;  // frame indices by palm orientation
  std::vector<std::string> left_out;      // recorded trials left out, each naming its file

  int size() const { return set.size(); }
};
using PoseSetPtr = std::shared_ptr<const LoadedPoseSet>;

// Builds a loaded pose set synchronously (what the worker runs; tests call it directly).
// Throws lmc::Error for a bad file. `on_progress(done, total)`: trials read (recordings only).
PoseSetPtr load_pose_set_for(const PoseSetChoice& choice, std::uint64_t version, std::stop_token stop = {},
                             const std::function<void(int, int)>& on_progress = {});

class PoseSetStore {
 public:
  // Starts loading `choice` unless it is already loaded or loading. Cheap to call every frame.
  void request(const PoseSetChoice& choice);
  // Picks up a finished load; call once per frame (update step).
  void poll();
  // Blocks until the current load finishes (tests and capture only).
  void wait();

  // Stops a load (reading recordings can take seconds); the set shown stays the one loaded before.
  void cancel();

  PoseSetPtr current() const { return current_; }
  bool loading() const { return job_.running(); }
  double progress() const { return job_.fraction(); }
  const std::string& error() const { return error_; }
  std::string stage() const { return job_.stage(); }

 private:
  PoseSetPtr current_;
  PoseSetChoice requested_;
  bool has_request_ = false;
  std::uint64_t next_version_ = 1;
  std::string error_;
  JobGraveyard graveyard_;  // a superseded load finishes here without blocking the frame
  BackgroundJob<PoseSetPtr, int> job_;
};

}  // namespace lmc::ui
