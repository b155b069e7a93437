#include "devices/fusion/live_fusion.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <utility>

#include "core/stats/percentile.h"

namespace lmc::devices {

LiveFusion::LiveFusion(const Layout& layout, LiveFusionOptions options)
    : layout_(layout), options_(std::move(options)), fusion_(layout_) {
  if (!options_.clock) options_.clock = host_now_ns;
  options_.queue_capacity = std::max<size_t>(options_.queue_capacity, 1);
  options_.latency_window = std::max<size_t>(options_.latency_window, 1);
  ring_.resize(options_.queue_capacity);
  latency_ms_.resize(options_.latency_window);
  worker_ = std::thread([this] { run(); });
}

LiveFusion::~LiveFusion() {
  stop();
}

void LiveFusion::stop() {
  {
    std::lock_guard lock(queue_mutex_);
    stopped_ = true;
  }
  queue_cv_.notify_all();  // the worker's wait looks at stopped_, not at a stop token
  if (worker_.joinable()) worker_.join();
}

void LiveFusion::tap(const HandFrame& frame) noexcept {
  const std::int64_t arrival = options_.clock();
  {
    std::lock_guard lock(queue_mutex_);
    if (stopped_) return;
    ++tapped_;
    const size_t capacity = ring_.size();
    if (count_ == capacity) {
      // Full: the oldest frame goes; the display only ever needs the newest hand.
      head_ = (head_ + 1) % capacity;
      --count_;
      ++dropped_;
    }
    Queued& slot = ring_[(head_ + count_) % capacity];
    slot.frame = frame;
    slot.arrival_ns = arrival;
    ++count_;
  }
  queue_cv_.notify_one();
}

void LiveFusion::run() {
  std::vector<Queued> batch;
  batch.reserve(ring_.size());  // the worker never allocates after this
  while (true) {
    batch.clear();
    {
      std::unique_lock lock(queue_mutex_);
      // A plain wait on stopped_, set and notified by stop(), as the recorder's writer waits: the
      // stop-token overload registers a std::stop_callback on every call, and with MinGW-w64's
      // libstdc++ (no futex: its semaphores wait on a condition variable) deregistering one while
      // stop() runs it can wait for ever, so stop()'s join hung the workbench under Wine (at exit;
      // most likely also the capture that once never ended in CI). The 100 ms bound looks again
      // whatever the runtime does with a notification.
      if (!queue_cv_.wait_for(lock, std::chrono::milliseconds(100), [this] { return count_ > 0 || stopped_; }))
        continue;
      if (stopped_) return;
      for (; count_ > 0; --count_) {
        batch.push_back(ring_[head_]);
        head_ = (head_ + 1) % ring_.size();
      }
    }
    std::int64_t fused = 0;
    std::int64_t refused = 0;
    for (const Queued& q : batch) {
      const int slot = q.frame.device_id - 1;
      if (slot < 0 || slot >= fusion_.slot_count()) {
        ++refused;
        continue;
      }
      try {
        fusion_.add(q.frame, slot, static_cast<double>(q.frame.timestamp_us) * 1e-6);
        ++fused;
      } catch (const std::exception&) {
        ++refused;  // a non-finite time: left out of the live view only, the recording keeps it
      }
    }
    if (fused == 0) {
      std::lock_guard lock(publish_mutex_);
      refused_ += refused;
      continue;
    }
    FusedHand hand = fusion_.current();
    const std::int64_t ready = options_.clock();
    std::lock_guard lock(publish_mutex_);
    latest_ = hand;
    ++published_;
    fused_ += fused;
    refused_ += refused;
    for (const Queued& q : batch) {
      latency_ms_[latency_next_] = static_cast<double>(ready - q.arrival_ns) * 1e-6;
      latency_next_ = (latency_next_ + 1) % latency_ms_.size();
      latency_count_ = std::min(latency_count_ + 1, latency_ms_.size());
    }
  }
}

std::optional<FusedHand> LiveFusion::latest() const {
  std::lock_guard lock(publish_mutex_);
  return latest_;
}

LiveFusionStats LiveFusion::stats() const {
  LiveFusionStats s;
  std::vector<double> window;
  {
    std::lock_guard lock(publish_mutex_);
    window.assign(latency_ms_.begin(), latency_ms_.begin() + static_cast<std::ptrdiff_t>(latency_count_));
    s.frames_fused = fused_;
    s.frames_refused = refused_;
    s.published = published_;
  }
  {
    std::lock_guard lock(queue_mutex_);
    s.frames_tapped = tapped_;
    s.frames_dropped = dropped_;
  }
  s.window_frames = window.size();
  if (!window.empty()) {
    s.latency_max_ms = *std::max_element(window.begin(), window.end());
    s.latency_p50_ms = percentile(window, 50);
    s.latency_p95_ms = percentile(std::move(window), 95);
  }
  return s;
}

}  // namespace lmc::devices
