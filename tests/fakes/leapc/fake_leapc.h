#pragma once
// Script and inspect the LeapC test double (LeapC.h beside this file). Tests queue service
// events; the backend's poll thread receives them through LeapPollConnection exactly as from
// the Ultraleap service: one message per poll, pointers valid only until the next poll (the
// double frees them then, so ASan catches a backend that keeps them), tracking events only for
// devices the client subscribed to (multi-device-aware connections, devices/leapc/README.md).
#include <cstdint>
#include <string>
#include <vector>

#include "LeapC.h"

namespace fake_leapc {

void reset();

// Service side.
void plug(std::uint32_t device_id, const std::string& serial);  // queues a Device event
void unplug(std::uint32_t device_id);                            // queues DeviceLost
// A DeviceFailure event. `with_handle`: hDevice is the handle the client opened for the device
// (the reference says it "may be NULL"); `with_message_device_id`: the message's device_id is set.
void device_failure(std::uint32_t device_id, eLeapDeviceStatus status, bool with_handle = false,
                    bool with_message_device_id = true);
// The next LeapSetPolicyFlagsEx calls for this device return `rs` (eLeapRS_Success clears it).
void fail_policy_ex(std::uint32_t device_id, eLeapRS rs);
// Policy flags set on one device with LeapSetPolicyFlagsEx (0 when never set).
std::uint64_t device_policy(std::uint32_t device_id);
void status_change(std::uint32_t device_id, std::uint32_t last_status, std::uint32_t status);
void dropped_frame(std::uint32_t device_id, std::int64_t frame_id);
void connection_lost();
void connection_event(std::uint32_t flags);

// A tracking event with the given hands (each a full LEAP_HAND).
void track(std::uint32_t device_id, std::int64_t frame_id, std::int64_t timestamp_us, float framerate,
           const std::vector<LEAP_HAND>& hands);
// A hand whose every joint encodes (base + joint index): palm = base, elbow = base + 1, …
LEAP_HAND make_hand(eLeapHandType type, float base);

// Client side, for assertions.
struct Stats {
  int connections_created = 0;
  int connections_opened = 0;
  int multi_device_aware = 0;  // LeapCreateConnection calls with the MultiDeviceAware flag
  int devices_opened = 0;
  int devices_closed = 0;
  int subscribed = 0;
  int unsubscribed = 0;
  int tracking_delivered = 0;
  int tracking_suppressed = 0;  // queued for a device nobody subscribed to
  int concurrent_polls = 0;
  std::uint64_t policy_set = 0;  // connection-wide flags (LeapSetPolicyFlags: the primary device only)
  int policy_ex_calls = 0;       // LeapSetPolicyFlagsEx calls (per device)
  int pending = 0;  // queued messages not yet polled
};
Stats stats();

}  // namespace fake_leapc
