#pragma once
// Ultraleap LeapC backend (devices/leapc/README.md): one multi-device-aware connection, one
// poll thread, N devices. Devices are discovered from Device events, opened, identified by serial
// and subscribed; tracking events are matched to their device by the message's device_id and
// turned into hand frames (the hand of the wanted type, the right by default); DeviceLost,
// failures, status changes and dropped frames are reported; a re-plug (possibly under a new id)
// is re-keyed by serial, and a lost service connection is waited out (LeapC reconnects by
// itself while polling). Everything is copied out of the message before the next poll.
//
// This header does not include LeapC.h, so the rest of the code base builds without the SDK.
// The .cpp compiles against the real SDK (when CMake finds it) or the test double under
// tests/fakes/leapc.
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/hand/hand_frame.h"
#include "devices/frame_source.h"

namespace lmc::devices {

struct LeapcOptions {
  std::uint32_t poll_timeout_ms = 100;
  HandType wanted_hand = HandType::kRight;  // the study measured the right hand
  bool background_frames = true;            // keep receiving frames when not focused (Windows)
};

class LeapcSource final : public FrameSource {
 public:
  explicit LeapcSource(LeapcOptions options = {});
  ~LeapcSource() override;

  std::string backend_name() const override { return "leapc"; }
  // Throws lmc::Error when the connection cannot be created.
  void start(FrameSink& sink) override;
  void stop() override;

 private:
  struct Impl;
  void run(FrameSink& sink);
  LeapcOptions options_;
  std::unique_ptr<Impl> impl_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// Lists the controllers the service reports within `wait_ms` (for `lmc devices`).
std::vector<DeviceInfo> leapc_list_devices(std::uint32_t wait_ms = 1500);

// Text for a LeapC result code / device status ("eLeapRS_Timeout", "BadTransport (USB link)").
std::string leapc_result_name(std::uint32_t rs);
std::string leapc_status_text(std::uint32_t status);

}  // namespace lmc::devices
