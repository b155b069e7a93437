#pragma once
// Script and inspect the LeapC test double (LeapC.h beside this file). Tests queue service
// events; the backend's poll thread receives them through LeapPollConnection exactly as from
// the Ultraleap service: one message per poll, pointers valid only until the next poll (the
// double frees them then, so ASan catches a backend that keeps them), tracking events only for
// devices the client subscribed to (multi-device-aware connections). Like the service, the double
// answers policy and tracking-mode requests asynchronously (a Policy / TrackingMode event for the
// device), numbers tracking frames twice (info.frame_id as scripted, tracking_frame_id
// consecutively per device), reports each device's product id, and can be told to refuse a
// policy, hold a tracking mode, fail opens and subscribes, or be unreachable at first.
#include <cstdint>
#include <string>
#include <vector>

#include "LeapC.h"

namespace fake_leapc {

void reset();

// Service side.
// Queues a Device event. `pid` is what LeapGetDeviceInfo reports; `mode` the tracking mode the
// device is in before anyone asks (another program may have left it in any).
void plug(std::uint32_t device_id, const std::string& serial, eLeapDevicePID pid = eLeapDevicePID_Peripheral,
          eLeapTrackingMode mode = eLeapTrackingMode_Desktop);
void unplug(std::uint32_t device_id);  // queues DeviceLost
// A DeviceFailure event. `with_handle`: hDevice is the handle the client opened for the device
// (the reference says it "may be NULL"); `with_message_device_id`: the message's device_id is set.
void device_failure(std::uint32_t device_id, eLeapDeviceStatus status, bool with_handle = false,
                    bool with_message_device_id = true);
// The next LeapSetPolicyFlagsEx calls for this device return `rs` (eLeapRS_Success clears it).
void fail_policy_ex(std::uint32_t device_id, eLeapRS rs);
// LeapSetPolicyFlagsEx succeeds for this device, but the service's answer (the Policy event)
// leaves out these flags: the request was refused.
void refuse_policy(std::uint32_t device_id, std::uint64_t flags);
// Policy flags set on one device with LeapSetPolicyFlagsEx (0 when never set).
std::uint64_t device_policy(std::uint32_t device_id);
// The service keeps this device in `mode` whatever is requested (another program holds it).
void hold_tracking_mode(std::uint32_t device_id, eLeapTrackingMode mode);
// The device's mode changes now (the control panel): a TrackingMode event is queued.
void change_tracking_mode(std::uint32_t device_id, eLeapTrackingMode mode);
// The mode last requested with LeapSetTrackingModeEx, or -1.
int requested_tracking_mode(std::uint32_t device_id);
// The next `times` LeapOpenDevice / LeapSubscribeEvents calls for this device fail with `rs`.
void fail_open(std::uint32_t device_id, int times, eLeapRS rs = eLeapRS_CannotOpenDevice);
void fail_subscribe(std::uint32_t device_id, int times, eLeapRS rs = eLeapRS_NotAvailable);
// The next `polls` LeapPollConnection calls return eLeapRS_NotConnected (the service is not up).
void not_connected_polls(int polls);
void status_change(std::uint32_t device_id, std::uint32_t last_status, std::uint32_t status);
void dropped_frame(std::uint32_t device_id, std::int64_t frame_id);
void connection_lost();
void connection_event(std::uint32_t flags);

// A tracking event with the given hands (each a full LEAP_HAND). `frame_id` is info.frame_id;
// tracking_frame_id counts this device's tracking events from 1.
void track(std::uint32_t device_id, std::int64_t frame_id, std::int64_t timestamp_us, float framerate,
           const std::vector<LEAP_HAND>& hands);
// A hand whose every joint encodes (base + joint index): palm = base, elbow = base + 1, …
LEAP_HAND make_hand(eLeapHandType type, float base);

// The double's LeapGetNow(): the host's steady clock in µs plus an offset (default 0), so a test
// can put the Leap clock far from the host clock, as it is.
void set_clock_offset_us(std::int64_t offset);
std::int64_t now_us();

// Client side, for assertions.
struct Stats {
  int connections_created = 0;
  int connections_opened = 0;
  int multi_device_aware = 0;  // LeapCreateConnection calls with the MultiDeviceAware flag
  int devices_opened = 0;
  int devices_closed = 0;
  int open_attempts = 0;  // LeapOpenDevice calls, failed ones included
  int subscribed = 0;
  int subscribe_attempts = 0;  // LeapSubscribeEvents calls, failed ones included
  int unsubscribed = 0;
  int tracking_delivered = 0;
  int tracking_suppressed = 0;  // queued for a device nobody subscribed to
  int concurrent_polls = 0;
  std::uint64_t policy_set = 0;   // connection-wide flags (LeapSetPolicyFlags: the primary device only)
  int policy_ex_calls = 0;        // LeapSetPolicyFlagsEx calls (per device)
  int tracking_mode_calls = 0;    // LeapSetTrackingModeEx calls (per device)
  int tracking_mode_queries = 0;  // LeapGetTrackingModeEx calls (per device)
  int pending = 0;                // queued messages not yet polled
};
Stats stats();

}  // namespace fake_leapc
