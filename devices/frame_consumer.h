#pragma once
// What the hub fans frames out to (the recorder). Both calls come from device threads, so an
// implementation must return quickly and never wait on the disk: offer() returns false when it
// had to drop the frame (the hub counts it against that device).
#include <cstdint>
#include <string>

#include "core/hand/hand_frame.h"
#include "devices/frame_source.h"

namespace lmc::devices {

class FrameConsumer {
 public:
  virtual ~FrameConsumer() = default;
  // `frame.device_id` is the slot number (LMC1 = 1). `may_wait` is true only for sources that
  // are not hardware-paced (simulated time): the consumer may then block until there is room.
  virtual bool offer(const HandFrame& frame, std::int64_t host_receive_ns, bool may_wait) = 0;
  // A device event, already mapped to its slot number (0 when unassigned).
  virtual void device_event(const DeviceEvent& event, int device_id, const std::string& slot) = 0;
  // The frame just accepted by offer() (same device and receive time) held the only hand in view,
  // classified as the other side and kept (SourceFrame::other_side_hand); the recorder counts them.
  virtual void other_side_hand(int /*device_id*/, std::int64_t /*host_receive_ns*/) {}
};

}  // namespace lmc::devices
