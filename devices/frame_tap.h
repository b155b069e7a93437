#pragma once
// A second, display-only listener on the hub's frames (the live fused hand). The
// recorder is the hub's one FrameConsumer and may apply back-pressure; a tap never may: it sees
// every frame of an assigned device after the recorder was offered it, and must return at once
// without blocking on anything slow (a tap that falls behind drops for itself, never for the
// recorder). Called from device threads, possibly several at once.
#include <cstdint>

#include "core/hand/hand_frame.h"

namespace lmc::devices {

class FrameTap {
 public:
  virtual ~FrameTap() = default;
  // `frame.device_id` is the slot number (LMC1 = 1); coordinates in the device's own frame.
  virtual void tap(const HandFrame& frame) noexcept = 0;
};

}  // namespace lmc::devices
