#include "devices/sim/sim_source.h"

#include <chrono>
#include <cmath>

#include "devices/host_clock.h"
#include "devices/platform/fine_timer.h"

namespace lmc::devices {

SimSource::SimSource(Layout layout, SimConfig config, SimSourceOptions options)
    : rig_(std::make_unique<SimRig>(std::move(layout), std::move(config))), options_(options) {}

SimSource::~SimSource() {
  stop();
}

void SimSource::start(FrameSink& sink) {
  if (thread_.joinable()) return;
  stop_ = false;
  thread_ = std::thread([this, &sink] { run(sink); });
}

void SimSource::set_go(double hold_s, std::function<void(std::int64_t host_ns)> on_go) {
  rig_->hold_start_pose(hold_s);
  on_go_ = std::move(on_go);
}

void SimSource::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void SimSource::run(FrameSink& sink) {
  const FineTimerResolution fine_sleeps;  // 120 Hz pacing on Windows too
  const std::int64_t start_ns = host_now_ns();
  start_ns_ = start_ns;
  bool completed = false;
  bool went = false;
  const double end = end_s();
  while (!stop_) {
    SimEvent e = rig_->next();
    if (end > 0 && e.time_s >= end) {
      completed = true;
      break;
    }
    if (options_.speed > 0) {
      const auto due_ns = start_ns + static_cast<std::int64_t>(e.time_s * 1e9 / options_.speed);
      // Sleep in short steps so stop() is prompt.
      for (;;) {
        const std::int64_t now = host_now_ns();
        if (now >= due_ns || stop_) break;
        std::this_thread::sleep_for(std::chrono::nanoseconds(std::min<std::int64_t>(due_ns - now, 20'000'000)));
      }
      if (stop_) break;
    }
    const std::int64_t host_ns =
        options_.speed > 0 ? host_now_ns() : start_ns + static_cast<std::int64_t>(std::llround(e.time_s * 1e9));
    if (!went && e.time_s >= go_s()) {
      went = true;
      if (on_go_) on_go_(host_ns);
    }
    sim_time_s_ = e.time_s;
    if (e.is_frame) {
      e.frame.host_receive_ns = host_ns;
      sink.on_frame(e.frame);
    } else {
      e.event.host_time_ns = host_ns;
      sink.on_device_event(e.event);
    }
  }
  finished_ = completed;
}

std::optional<std::int64_t> SimSource::device_clock_us(std::int64_t host_ns) const {
  const std::int64_t start_ns = start_ns_.load();
  if (start_ns == 0 || options_.speed <= 0) return std::nullopt;
  // Events are due at start_ns + t / speed (run()), stamped device_clock_start_us + t.
  const double t_us = static_cast<double>(host_ns - start_ns) * options_.speed / 1000.0;
  return rig_->config().device_clock_start_us + static_cast<std::int64_t>(std::llround(t_us));
}

std::vector<HandFrame> SimSource::truth_until(double seconds) const {
  std::vector<HandFrame> out;
  const double rate = rig_->config().truth_rate_hz;
  const auto n = static_cast<int>(std::floor(seconds * rate + 1e-9));
  out.reserve(static_cast<size_t>(std::max(0, n)));
  for (int i = 0; i < n; ++i) out.push_back(rig_->truth_at(i / rate));
  return out;
}

}  // namespace lmc::devices
