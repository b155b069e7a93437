#pragma once
// Listens to a running hub for a moment and tells, per layout slot, which controller streamed
// and at what rate, from the devices' own timestamps, so the answer is the same in real time
// and in simulated time. The pre-flight check reads it.
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <stop_token>
#include <vector>

#include "devices/device_hub.h"
#include "devices/frame_consumer.h"
#include "devices/session_runner/preflight.h"

namespace lmc::devices {

class StreamProbe final : public FrameConsumer {
 public:
  bool offer(const HandFrame& frame, std::int64_t host_receive_ns, bool may_wait) override;
  void device_event(const DeviceEvent& event, int device_id, const std::string& slot) override;

  // Frames seen from the device in slot number `device_id` (LMC1 = 1).
  std::int64_t frames(int device_id) const;
  // Rate from the first to the last timestamp seen (0 with fewer than two frames).
  double rate_hz(int device_id) const;

 private:
  struct Seen {
    std::int64_t frames = 0;
    std::int64_t first_us = 0, last_us = 0;
  };
  mutable std::mutex mutex_;
  std::map<int, Seen> seen_;
};

// Attaches a probe to `hub` (which must have no other consumer; a hub not running yet is started
// after the probe is attached, so no frame goes unseen) until every slot has sent `frames_wanted`
// frames or `timeout` passes (for a hub faster than real time: its sources' end, or two minutes),
// then detaches it and describes each slot.
std::vector<SlotProbe> probe_streams(DeviceHub& hub, std::chrono::milliseconds timeout, std::int64_t frames_wanted,
                                     std::stop_token stop = {});

}  // namespace lmc::devices
