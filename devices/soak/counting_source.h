#pragma once
// A frame source that keeps, beside the frames it passes on, the host time of every frame its
// inner source produced: the count a soak checks the file against. It is taken from the source's
// side of the hub on purpose, so a frame lost anywhere after it (the hub, the recorder's queue,
// the writer, the disk) shows as a difference, whichever part lost it.
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "devices/frame_source.h"

namespace lmc::devices {

class CountingSource final : public FrameSource, private FrameSink {
 public:
  explicit CountingSource(std::unique_ptr<FrameSource> inner);
  ~CountingSource() override;

  std::string backend_name() const override { return inner_->backend_name(); }
  void start(FrameSink& sink) override;
  void stop() override;
  bool realtime() const override { return inner_->realtime(); }
  bool finished() const override { return inner_->finished(); }
  std::optional<std::int64_t> device_clock_us(std::int64_t host_ns) const override {
    return inner_->device_clock_us(host_ns);
  }

  // The host receive times of the frames produced since the previous call, in order (any thread).
  std::vector<std::int64_t> take_frame_times();
  std::int64_t frames_produced() const;

 private:
  void on_device_event(const DeviceEvent& event) override;
  void on_frame(const SourceFrame& frame) override;

  std::unique_ptr<FrameSource> inner_;
  FrameSink* sink_ = nullptr;
  mutable std::mutex mutex_;
  std::vector<std::int64_t> times_;
  std::int64_t produced_ = 0;
};

}  // namespace lmc::devices
