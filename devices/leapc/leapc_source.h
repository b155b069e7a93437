#pragma once
// Ultraleap LeapC backend: one multi-device-aware connection, one poll thread, N devices.
// Devices are discovered from Device events, opened, identified by serial and subscribed; a
// device is announced (and shown as connected) only once it is subscribed, and a failed open or
// subscribe is retried. Two devices reporting one serial are refused, so two controllers never
// share a slot. Each device is asked for background frames and for the tracking mode its layout
// pose implies; the service answers both asynchronously (Policy and TrackingMode events), and a
// refusal or another mode is reported. Tracking events are matched to their device by the
// message's device_id and turned into hand frames with the service's image frame id (what the
// study's files hold); the hand of the wanted side is kept, and when the only hand in view is
// classified as the other side it is kept too and marked (HandFrame::other_side_hand). Lost
// devices, failures, status changes and dropped frames (summed per device and second) are
// reported; a re-plug is re-keyed by serial, and a lost service connection is waited out (LeapC
// reconnects by itself while polling). Everything is copied out of a message before the next poll.
//
// This header does not include LeapC.h, so the rest of the code base builds without the SDK.
// The .cpp compiles against the real SDK (when CMake finds it) or the test double under
// tests/fakes/leapc.
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/hand/hand_frame.h"
#include "core/layout/layout.h"
#include "devices/frame_source.h"

namespace lmc::devices {

struct LeapcOptions {
  std::uint32_t poll_timeout_ms = 100;
  HandType wanted_hand = HandType::kRight;  // the study measured the right hand
  bool background_frames = true;            // keep receiving frames when not focused (Windows)
  // Where the controllers stand: a controller whose serial the layout binds to a slot posed
  // looking down gets screen-top mode, every other one desktop (devices/tracking_mode.h).
  Layout layout;
  // Off: devices keep whatever mode they are in (a listing must not change the rig).
  bool request_tracking_mode = true;
  // A device that cannot be opened or subscribed to is tried again this often, this many times.
  std::uint32_t retry_interval_ms = 500;
  int max_attempts = 10;
};

class LeapcSource final : public FrameSource {
 public:
  explicit LeapcSource(LeapcOptions options = {});
  ~LeapcSource() override;

  std::string backend_name() const override { return "leapc"; }
  // Throws lmc::Error when the connection cannot be created.
  void start(FrameSink& sink) override;
  void stop() override;
  // LeapGetNow(), the clock of every frame timestamp, moved to `host_ns`.
  std::optional<std::int64_t> device_clock_us(std::int64_t host_ns) const override;

 private:
  struct Impl;
  void run(FrameSink& sink);
  LeapcOptions options_;
  std::unique_ptr<Impl> impl_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> running_{false};
  std::thread thread_;
};

// Lists the controllers the service reports within `wait_ms` (for `lmc devices`).
std::vector<DeviceInfo> leapc_list_devices(std::uint32_t wait_ms = 1500);

// Text for a LeapC result code / device status ("eLeapRS_Timeout", "BadTransport (USB link)").
std::string leapc_result_name(std::uint32_t rs);
std::string leapc_status_text(std::uint32_t status);
// The product name of a LeapC product id (LEAP_DEVICE_INFO::pid): "Leap Motion Controller",
// "Leap Motion Controller 2", "Stereo IR 170", … or "Ultraleap device (product id 0x1234)".
std::string leapc_model_name(std::uint32_t pid);

}  // namespace lmc::devices
