#include "devices/soak/counting_source.h"

#include <utility>

namespace lmc::devices {

CountingSource::CountingSource(std::unique_ptr<FrameSource> inner) : inner_(std::move(inner)) {}

CountingSource::~CountingSource() {
  stop();
}

void CountingSource::start(FrameSink& sink) {
  sink_ = &sink;
  inner_->start(*this);
}

void CountingSource::stop() {
  inner_->stop();
}

std::vector<std::int64_t> CountingSource::take_frame_times() {
  std::lock_guard lock(mutex_);
  return std::exchange(times_, {});
}

std::int64_t CountingSource::frames_produced() const {
  std::lock_guard lock(mutex_);
  return produced_;
}

void CountingSource::on_device_event(const DeviceEvent& event) {
  sink_->on_device_event(event);
}

void CountingSource::on_frame(const SourceFrame& frame) {
  {
    std::lock_guard lock(mutex_);
    times_.push_back(frame.host_receive_ns);
    ++produced_;
  }
  sink_->on_frame(frame);
}

}  // namespace lmc::devices
