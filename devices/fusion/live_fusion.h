#pragma once
// The live fused hand (the paper's future work: fusion on a thread of its own, apart
// from the threads reading the controllers). A LiveFusion is a hub tap (frame_tap.h) that queues
// every frame the hub delivers and a worker thread that feeds each one, in arrival order, to the
// causal default fusion (core/processing/online_fusion.h: ray-traced seen-by counts, Kalman
// filter) and publishes the latest fused hand.
//
// Never in the recorder's way: tap() copies the frame into a bounded queue under a short lock and
// returns; when the worker falls behind, the oldest queued frame is dropped (and counted), since
// only the newest hand matters for display. Recording is untouched: the recorder is offered the
// frame before any tap.
//
// Latency: from the frame's arrival at the hub (the host clock read in tap()) to the fused hand
// that includes it being published, kept over a sliding window of the latest frames (p50, p95,
// max). The worker takes every frame queued at once and publishes once per batch, so under load
// it does less work per frame instead of falling further behind.
#include <condition_variable>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "core/layout/layout.h"
#include "core/processing/online_fusion.h"
#include "devices/frame_tap.h"
#include "devices/host_clock.h"

namespace lmc::devices {

struct LiveFusionOptions {
  size_t queue_capacity = 64;     // frames waiting for the worker (≈ 130 ms at 4 × 120 Hz)
  size_t latency_window = 2048;   // frames the percentiles are taken over (≈ 4 s at 4 × 120 Hz)
  HostClock clock = host_now_ns;  // arrival and publish times
};

struct LiveFusionStats {
  // Arrival at the hub → fused hand published, over the window; NaN before the first frame.
  double latency_p50_ms = std::numeric_limits<double>::quiet_NaN();
  double latency_p95_ms = std::numeric_limits<double>::quiet_NaN();
  double latency_max_ms = std::numeric_limits<double>::quiet_NaN();
  size_t window_frames = 0;         // frames the percentiles describe
  std::int64_t frames_tapped = 0;   // every frame the hub handed over
  std::int64_t frames_fused = 0;    // fed to the fusion
  std::int64_t frames_dropped = 0;  // the queue was full: dropped from the display only
  std::int64_t frames_refused = 0;  // the fusion refused them (slot outside the layout, bad time)
  std::uint64_t published = 0;      // fused hands published so far
};

class LiveFusion final : public FrameTap {
 public:
  // `layout` must be the hub's (slot numbers index its devices). Starts the worker. Throws
  // lmc::Error for a layout the fusion refuses.
  explicit LiveFusion(const Layout& layout, LiveFusionOptions options = {});
  ~LiveFusion() override;  // stops and joins
  LiveFusion(const LiveFusion&) = delete;
  LiveFusion& operator=(const LiveFusion&) = delete;

  void tap(const HandFrame& frame) noexcept override;

  // Stops and joins the worker; frames tapped afterwards are ignored. Safe to call twice.
  void stop();
  // The latest fused hand (nullopt before the first one). Any thread.
  std::optional<FusedHand> latest() const;
  LiveFusionStats stats() const;
  const Layout& layout() const { return layout_; }

 private:
  struct Queued {
    HandFrame frame;
    std::int64_t arrival_ns = 0;
  };
  void run();

  Layout layout_;
  LiveFusionOptions options_;
  OnlineFusion fusion_;  // the worker's alone

  // The queue: a ring of queue_capacity slots, allocated once.
  mutable std::mutex queue_mutex_;
  std::condition_variable queue_cv_;
  std::vector<Queued> ring_;
  size_t head_ = 0;  // oldest
  size_t count_ = 0;
  bool stopped_ = false;
  std::int64_t tapped_ = 0;
  std::int64_t dropped_ = 0;

  // What the worker publishes.
  mutable std::mutex publish_mutex_;
  std::optional<FusedHand> latest_;
  std::vector<double> latency_ms_;  // ring of latency_window samples
  size_t latency_next_ = 0;
  size_t latency_count_ = 0;
  std::int64_t fused_ = 0;
  std::int64_t refused_ = 0;
  std::uint64_t published_ = 0;

  std::thread worker_;  // last: started when everything above exists, joined first
};

}  // namespace lmc::devices
