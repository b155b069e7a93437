#pragma once
// Plays a SimRig as live devices: a thread delivers each event when its simulated time comes
// (speed 1 = real time, 4 = four times faster) or as fast as the sink takes them (speed 0; not
// hardware-paced, so realtime() is false and the hub may apply back-pressure).
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "devices/frame_source.h"
#include "devices/sim/sim_rig.h"

namespace lmc::devices {

struct SimSourceOptions {
  double speed = 1.0;       // 0: as fast as possible
  double duration_s = 0.0;  // the trial's length after go (0: forever)
};

class SimSource final : public FrameSource {
 public:
  SimSource(Layout layout, SimConfig config, SimSourceOptions options = {});
  ~SimSource() override;

  std::string backend_name() const override { return "sim"; }
  void start(FrameSink& sink) override;
  void stop() override;
  bool realtime() const override { return options_.speed > 0; }
  bool finished() const override { return finished_.load(); }
  // The simulated device clock (SimConfig::device_clock_start_us + simulated time) at `host_ns`,
  // as LeapGetNow would read it; nullopt before start() and when not in real time (speed 0).
  std::optional<std::int64_t> device_clock_us(std::int64_t host_ns) const override;

  const std::vector<DeviceInfo>& devices() const { return rig_->devices(); }
  // A trial with a countdown: the hand holds still for `hold_s` simulated seconds, then moves;
  // `on_go` runs on the source's thread just before the first event at or after `hold_s`, with
  // that event's host time, so a recorder opened there starts exactly at go whatever the speed.
  // Call before start().
  void set_go(double hold_s, std::function<void(std::int64_t host_ns)> on_go);
  double go_s() const { return rig_->hold_s(); }
  // The trial's length after go (0: runs until stopped) and the simulated time it stops at.
  double duration_s() const { return options_.duration_s; }
  double end_s() const { return options_.duration_s > 0 ? go_s() + options_.duration_s : 0.0; }
  // Simulated seconds delivered so far.
  double simulated_time_s() const { return sim_time_s_.load(); }
  // Ground truth collected at the truth rate for the delivered span (call after stop()).
  std::vector<HandFrame> truth_until(double seconds) const;
  const SimRig& rig() const { return *rig_; }

 private:
  void run(FrameSink& sink);
  std::unique_ptr<SimRig> rig_;
  SimSourceOptions options_;
  std::function<void(std::int64_t)> on_go_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> finished_{false};
  std::atomic<double> sim_time_s_{0};
  std::atomic<std::int64_t> start_ns_{0};  // host time of simulated time 0 (0 before start)
  std::thread thread_;
};

}  // namespace lmc::devices
