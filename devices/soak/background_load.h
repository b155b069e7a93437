#pragma once
// The work a workbench does beside a recording, headless, on one thread (one core of two): the
// Layout tab's placement heatmap, a placement search, and processing of the trial just recorded
// (as Review does when a trial comes in). A soak runs it so the recorder is measured with the
// machine as busy as a lab's, not idle. Each round takes the three in turn; stop() ends the
// current one at its next check (the heatmap and the search stop at once, a processing run
// finishes first).
#include <cstdint>
#include <memory>
#include <mutex>
#include <stop_token>
#include <string>
#include <thread>

#include "core/io/lmc_recording.h"
#include "core/layout/layout.h"

namespace lmc::devices {

struct BackgroundLoadCounts {
  std::int64_t heatmaps = 0;          // full placement heatmap sweeps
  std::int64_t searches = 0;          // placement searches (short PSO runs)
  std::int64_t trials_processed = 0;  // trials through the processing pipeline
  std::string last_error;             // a processing error (the work goes on)
};

class BackgroundLoad {
 public:
  // `layout`: the heatmap, the search and processing use its first kMaxDevices controllers.
  // `pose_frames`: the pose-set size the heatmap and search run on.
  explicit BackgroundLoad(const Layout& layout, int pose_frames = 1000);
  ~BackgroundLoad();
  BackgroundLoad(const BackgroundLoad&) = delete;
  BackgroundLoad& operator=(const BackgroundLoad&) = delete;

  void start();
  void stop();  // joins
  // The next round processes this recording (the rows of the first kMaxDevices controllers).
  void process_next(std::shared_ptr<const LmcRecording> recording);
  BackgroundLoadCounts counts() const;

 private:
  void run(const std::stop_token& stop);
  void process_latest();  // the recording given last, if any
  Layout layout_;
  int pose_frames_;
  mutable std::mutex mutex_;
  std::shared_ptr<const LmcRecording> next_;
  BackgroundLoadCounts counts_;
  std::jthread thread_;  // last: started when everything above exists
};

}  // namespace lmc::devices
