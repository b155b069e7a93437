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
// LeapC is loaded at run time (leapc_library.h): start() finds the library, or throws with every
// place tried; the library and the service's versions are the first device message. The poll
// loop handles a message completely before anything that may close a device, and stop() closes
// the connection before it joins, so a poll that blocks past its timeout cannot hang it.
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
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
  // The service answers a new device's policy and mode requests late, and sends the policies it
  // had before: a refusal or another mode is reported only if it still holds this long after the
  // device was subscribed.
  std::uint32_t warning_grace_ms = 3000;
  // A service that neither connects nor refuses (every poll times out) is asked for its state
  // (LeapGetConnectionInfo) after this long, and named when it is not running.
  std::uint32_t service_check_ms = 2000;
  // stop() waits this long for the poll thread after closing the connection; a thread still stuck
  // in LeapC after that is left to finish on its own (it touches nothing of the caller's).
  std::uint32_t stop_timeout_ms = 2000;
};

class LeapcSource final : public FrameSource {
 public:
  explicit LeapcSource(LeapcOptions options = {});
  ~LeapcSource() override;

  std::string backend_name() const override { return "leapc"; }
  // Throws lmc::Error when the connection cannot be created.
  void start(FrameSink& sink) override;
  void stop() override;
  // LeapGetNow(), the clock of every frame timestamp, moved to `host_ns`: the best of several
  // host/Leap/host brackets (the narrowest), so a thread switch between two reads costs nothing.
  std::optional<std::int64_t> device_clock_us(std::int64_t host_ns) const override;
  // The half-width of the narrowest bracket behind the latest device_clock_us, µs.
  std::optional<std::int64_t> device_clock_uncertainty_us() const override;

 private:
  struct Impl;
  std::shared_ptr<Impl> current_impl() const;
  LeapcOptions options_;
  mutable std::mutex impl_mutex_;
  std::shared_ptr<Impl> impl_;  // the running connection (null when stopped)
  std::thread thread_;
  mutable std::atomic<std::int64_t> clock_uncertainty_us_{-1};
};

// Lists the controllers the service reports within `wait_ms` (for `lmc devices`). `notices`, when
// given, receives the backend's messages (the library loaded, the service's version, …).
std::vector<DeviceInfo> leapc_list_devices(std::uint32_t wait_ms = 1500, std::vector<std::string>* notices = nullptr);

// Text for a LeapC result code / device status ("eLeapRS_Timeout", "BadTransport (USB link)").
std::string leapc_result_name(std::uint32_t rs);
std::string leapc_status_text(std::uint32_t status);
// The product name of a LeapC product id (LEAP_DEVICE_INFO::pid): "Leap Motion Controller",
// "Leap Motion Controller 2", "Stereo IR 170", … or "Ultraleap device (product id 0x1234)".
std::string leapc_model_name(std::uint32_t pid);

}  // namespace lmc::devices
