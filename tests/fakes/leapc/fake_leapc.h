#pragma once
// Script and inspect the LeapC test double. The double is a shared library named as Ultraleap's
// (libLeapC.so.5, target lmc_fake_leapc) exporting the LeapC functions the backend looks up, built
// from devices/leapc/leapc_abi.h, so the backend loads it at run time exactly as it loads the real
// one. Tests link it too and script the service through the functions below.
//
// It is as strict as the service, by default:
//  * a Connection event on a normal start (after LeapOpenConnection);
//  * a Device event is followed by a DeviceStatusChange (idle → streaming) and a Policy event with
//    the device's policies before anyone asked (none);
//  * a lost service sends DeviceLost for every device, then ConnectionLost; reconnect() sends a
//    Connection event and announces every device again under new ids;
//  * a tracking-mode request takes effect a few polls later (a query made at once answers with the
//    old mode);
//  * some polls overrun their timeout;
//  * one message per poll, valid until the next poll or until any device is closed (then it is
//    freed, so ASan catches a backend that reads it afterwards);
//  * tracking events only for subscribed devices; tracking frames numbered twice (info.frame_id as
//    scripted, tracking_frame_id consecutively per device);
//  * LeapGetNow() drifts 50 ppm against the host's steady clock, from an offset.
// It can also refuse a policy, hold a tracking mode, fail opens, serial reads and subscribes, be
// unreachable at first or silent (polls only time out), block polls, send log events, and make
// LeapGetNow slow (a thread switch between two clock reads).
#include <cstdint>
#include <string>
#include <vector>

#include "devices/leapc/leapc_abi.h"

namespace fake_leapc {

namespace leapc = lmc::devices::leapc;

// Text the double's library carries (fake_leapc_api.cpp exports it): a test that finds a LeapC in
// a machine-wide place tells an earlier run's double, which it may replace, from Ultraleap's own.
inline constexpr char kMarker[] = "lmc-workbench LeapC test double";

inline constexpr std::uint32_t kPidPeripheral = 0x0003;  // Leap Motion Controller
inline constexpr std::uint32_t kPidSir170 = 0x1203;
inline constexpr std::uint32_t kPidLmc2 = 0x1206;

void reset();

// Service side.
// Queues a Device event (then the status change and Policy event). `pid` is what
// LeapGetDeviceInfo reports; `mode` the tracking mode the device is in before anyone asks.
void plug(std::uint32_t device_id, const std::string& serial, std::uint32_t pid = kPidPeripheral,
          std::uint32_t mode = leapc::kModeDesktop);
// Only the Device event, as `plug` queues it first: the service announcing an id again.
void announce(std::uint32_t device_id);
void unplug(std::uint32_t device_id);  // queues DeviceLost
// A DeviceFailure event. `with_handle`: hDevice is the handle the client opened for the device
// (the reference says it "may be NULL"); `with_message_device_id`: the message's device_id is set.
void device_failure(std::uint32_t device_id, std::uint32_t status, bool with_handle = false,
                    bool with_message_device_id = true);
// The next LeapSetPolicyFlagsEx calls for this device return `rs` (kSuccess clears it).
void fail_policy_ex(std::uint32_t device_id, leapc::Result rs);
// LeapSetPolicyFlagsEx succeeds for this device, but the service's answer (the Policy event)
// leaves out these flags: the request was refused.
void refuse_policy(std::uint32_t device_id, std::uint64_t flags);
std::uint64_t device_policy(std::uint32_t device_id);  // set with LeapSetPolicyFlagsEx (0 when never)
// The service keeps this device in `mode` whatever is requested (another program holds it).
void hold_tracking_mode(std::uint32_t device_id, std::uint32_t mode);
// The device's mode changes now (the control panel): a TrackingMode event is queued.
void change_tracking_mode(std::uint32_t device_id, std::uint32_t mode);
int requested_tracking_mode(std::uint32_t device_id);  // the last LeapSetTrackingModeEx mode, or -1
// A tracking-mode request takes effect this many polls later (default 3; 0 = at once).
void set_mode_delay_polls(int polls);
// The next `times` LeapOpenDevice / LeapSubscribeEvents / serial reads for this device fail.
void fail_open(std::uint32_t device_id, int times, leapc::Result rs = leapc::kCannotOpenDevice);
void fail_subscribe(std::uint32_t device_id, int times, leapc::Result rs = leapc::kNotAvailable);
void fail_serial(std::uint32_t device_id, int times, leapc::Result rs = leapc::kUnknownError);
// The next `polls` LeapPollConnection calls return kNotConnected (the service is not up).
void not_connected_polls(int polls);
// The service never answers: polls only time out and LeapGetConnectionInfo says "not running".
void silent_service(bool silent);
// Polls ignore their timeout and return only when the connection is closed (or after `max_ms`,
// so a backend that waits for them is slow, not hung).
void block_polls(bool block, int max_ms = 1500);
// Every `every`-th poll that times out returns `extra_ms` late (default every 7th, 3 ms).
void set_poll_overrun(int every, int extra_ms);
void status_change(std::uint32_t device_id, std::uint32_t last_status, std::uint32_t status);
void dropped_frame(std::uint32_t device_id, std::int64_t frame_id);
void log_event(std::uint32_t severity, const std::string& message);
void connection_lost();  // DeviceLost for every device, then ConnectionLost
// The service is back: a Connection event, then every device announced again under id + offset;
// returns the new ids in the order of the old ones.
std::vector<std::uint32_t> reconnect(std::uint32_t id_offset = 100);
void connection_event(std::uint32_t flags);

// A tracking event with the given hands. `frame_id` is info.frame_id; tracking_frame_id counts
// this device's tracking events from 1.
void track(std::uint32_t device_id, std::int64_t frame_id, std::int64_t timestamp_us, float framerate,
           const std::vector<leapc::Hand>& hands);
// A hand whose every joint encodes (base + joint index): palm = base, elbow = base + 1, …
leapc::Hand make_hand(std::uint32_t type, float base);

// LeapGetNow(): the host's steady clock in µs, running 50 ppm fast from the moment of reset(),
// plus an offset (default 0), so a test can put the Leap clock far from the host clock, as it is.
void set_clock_offset_us(std::int64_t offset);
std::int64_t now_us();                                // what LeapGetNow() returns now, never slowed
void slow_get_now(int calls, std::int64_t delay_us);  // the next `calls` LeapGetNow() take this long
// LeapGetVersion's answers (client library and service); default 5.6.1, or LMC_FAKE_LEAPC_VERSION.
void set_version(int major, int minor, int patch);

// Client side, for assertions.
struct Stats {
  int connections_created = 0;
  int connections_opened = 0;
  int connections_closed = 0;
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
  int policy_ex_calls = 0;        // LeapSetPolicyFlagsEx calls (per device)
  int tracking_mode_calls = 0;    // LeapSetTrackingModeEx calls (per device)
  int tracking_mode_queries = 0;  // LeapGetTrackingModeEx calls (per device)
  int open_handles = 0;           // devices opened and not closed
  int pending = 0;                // queued messages not yet polled
};
Stats stats();

}  // namespace fake_leapc
