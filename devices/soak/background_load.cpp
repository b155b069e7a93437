#include "devices/soak/background_load.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <stop_token>
#include <utility>

#include "core/io/pose_source.h"
#include "core/metric/placement_heatmap.h"
#include "core/optimise/pso.h"
#include "core/optimise/search_space.h"
#include "core/processing/trial_pipeline.h"
#include "core/visibility/frame_prep.h"
#include "devices/soak/grouped_fusion.h"

namespace lmc::devices {

BackgroundLoad::BackgroundLoad(const Layout& layout, int pose_frames)
    : layout_(layout_slice(layout, 0, std::min(kMaxDevices, layout.device_count()))), pose_frames_(pose_frames) {}

BackgroundLoad::~BackgroundLoad() {
  stop();
}

void BackgroundLoad::start() {
  if (thread_.joinable()) return;
  thread_ = std::jthread([this](const std::stop_token& stop) { run(stop); });
}

void BackgroundLoad::stop() {
  if (!thread_.joinable()) return;
  thread_.request_stop();
  thread_.join();
}

void BackgroundLoad::process_next(std::shared_ptr<const LmcRecording> recording) {
  std::lock_guard lock(mutex_);
  next_ = std::move(recording);
}

BackgroundLoadCounts BackgroundLoad::counts() const {
  std::lock_guard lock(mutex_);
  return counts_;
}

void BackgroundLoad::run(const std::stop_token& stop) {
  // One core: every parallel loop below runs inside an arena of one thread.
  tbb::task_arena arena(1);
  try {
    arena.execute([&] {
      const std::vector<PreparedFrame> frames = prepare_frames(load_poses("mc", pose_frames_).frames);
      for (int round = 0; !stop.stop_requested(); ++round) {
        // Coarse to fine, as the Layout tab sweeps: a quarter, a half, then the full 48 cells.
        for (const int cells : {12, 24, 48}) {
          HeatmapSpec spec;
          spec.device = round % layout_.device_count();
          spec.cells = cells;
          if (!sweep_placement_heatmap(layout_, frames, spec, stop)) break;
          std::lock_guard lock(mutex_);
          ++counts_.heatmaps;
        }
        if (stop.stop_requested()) break;
        PsoSettings pso;
        pso.particles = 10;
        pso.iterations = 3;
        pso.threads = 1;
        pso.seed = static_cast<std::uint64_t>(round + 1);
        if (run_pso(layout_, SearchSpace{}, frames, pso, {}, stop).status == JobStatus::kCompleted) {
          std::lock_guard lock(mutex_);
          ++counts_.searches;
        }
        if (stop.stop_requested()) break;
        process_latest();
      }
    });
  } catch (const std::exception& e) {
    // The load is gone, not the soak: it reports the error and records on.
    std::lock_guard lock(mutex_);
    counts_.last_error = std::string("background load stopped: ") + e.what();
  }
}

void BackgroundLoad::process_latest() {
  std::shared_ptr<const LmcRecording> recording;
  {
    std::lock_guard lock(mutex_);
    recording = std::exchange(next_, nullptr);
  }
  if (!recording) return;
  LmcRecording mine;
  mine.kind = recording->kind;
  for (const HandFrame& f : recording->rows)
    if (f.device_id >= 1 && f.device_id <= layout_.device_count()) mine.rows.push_back(f);
  std::string error;
  try {
    (void)process_trial("soak", mine, layout_, nullptr, ProcessOptions{});
  } catch (const std::exception& e) {
    error = e.what();
  }
  std::lock_guard lock(mutex_);
  ++counts_.trials_processed;
  if (!error.empty()) counts_.last_error = error;
}

}  // namespace lmc::devices
