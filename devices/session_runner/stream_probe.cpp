#include "devices/session_runner/stream_probe.h"

#include <algorithm>
#include <thread>

namespace lmc::devices {
namespace {
constexpr std::chrono::milliseconds kSimulatedProbeLimit{120'000};
}  // namespace

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
  // Started only once the probe listens: a simulated source played faster than real time
  // delivers its two seconds in a few milliseconds, and the thread that start() creates may run
  // them all before this thread, descheduled on a busy machine (or under Wine), attaches anyone.
  if (!hub.running()) hub.start();
  const int slots = hub.layout().device_count();
  // A hub that plays simulated time faster than real time (lmc session run --fast) streams as fast
  // as the machine lets it: the wall clock then measures the machine, not the controllers, and a
  // starved one (a busy CI machine; Wine, whose every wait goes through its wineserver) can take
  // many times `timeout` for the frames a real controller sends in it. Its source is finite, so
  // the probe waits for the frames or the source's end, with a far deadline only against a hang.
  const auto wait = hub.realtime() ? timeout : std::max(timeout, kSimulatedProbeLimit);
  const auto deadline = std::chrono::steady_clock::now() + wait;
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
