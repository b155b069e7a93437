#include "devices/session_runner/stream_probe.h"

#include <thread>

namespace lmc::devices {

bool StreamProbe::offer(const HandFrame& frame, std::int64_t /*host_receive_ns*/, bool /*may_wait*/) {
  std::lock_guard lock(mutex_);
  Seen& s = seen_[frame.device_id];
  if (s.frames == 0) s.first_us = frame.timestamp_us;
  s.last_us = frame.timestamp_us;
  ++s.frames;
  return true;
}

void StreamProbe::device_event(const DeviceEvent& /*event*/, int /*device_id*/, const std::string& /*slot*/) {}

std::int64_t StreamProbe::frames(int device_id) const {
  std::lock_guard lock(mutex_);
  auto it = seen_.find(device_id);
  return it == seen_.end() ? 0 : it->second.frames;
}

double StreamProbe::rate_hz(int device_id) const {
  std::lock_guard lock(mutex_);
  auto it = seen_.find(device_id);
  if (it == seen_.end() || it->second.frames < 2 || it->second.last_us <= it->second.first_us) return 0;
  return static_cast<double>(it->second.frames - 1) * 1e6 /
         static_cast<double>(it->second.last_us - it->second.first_us);
}

std::vector<SlotProbe> probe_streams(DeviceHub& hub, std::chrono::milliseconds timeout, std::int64_t frames_wanted,
                                     std::stop_token stop) {
  StreamProbe probe;
  hub.set_consumer(&probe);
  const int slots = hub.layout().device_count();
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    bool all = true;
    for (int id = 1; id <= slots; ++id) all = all && probe.frames(id) >= frames_wanted;
    if (all || hub.sources_finished() || stop.stop_requested() || std::chrono::steady_clock::now() >= deadline) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  hub.set_consumer(nullptr);

  const HubSnapshot snap = hub.snapshot();
  std::vector<SlotProbe> out;
  for (int i = 0; i < slots; ++i) {
    const auto& device = hub.layout().devices[static_cast<size_t>(i)];
    SlotProbe p;
    p.slot = device.slot;
    p.bound_serial = device.serial.value_or("");
    for (const auto& d : snap.devices)
      if (d.slot_index == i) p.serial = d.serial;
    p.frames = probe.frames(i + 1);
    p.rate_hz = probe.rate_hz(i + 1);
    out.push_back(p);
  }
  return out;
}

}  // namespace lmc::devices
