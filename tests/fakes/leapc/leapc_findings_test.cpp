// What a read of the backend against the real LeapC header, the study's program and Ultraleap's
// own plugins found, each held by a test against the strict double (fake_leapc.h): a stop that
// cannot hang on a blocked poll, re-plugged and restarted devices never lost, a serial that cannot
// be read never a placeholder slot, no message read after a device was closed, no false warnings
// at start, one count per dropped frame, a silent service named, the service's log shown, no row
// before a device streams, and the device clock read in the narrowest of several brackets.
#include <chrono>
#include <initializer_list>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "devices/device_hub.h"
#include "devices/host_clock.h"
#include "devices/leapc/leapc_source.h"
#include "fake_leapc.h"
#include "leapc_test_support.h"

namespace lmc::devices {
namespace {

class LeapcFinding : public ::testing::Test {
 protected:
  void SetUp() override { fake_leapc::reset(); }
  void TearDown() override { fake_leapc::reset(); }

  bool wait_message(DeviceHub& hub, std::initializer_list<const char*> parts, int timeout_ms = 3000) {
    return wait_for(
        [&] {
          for (auto& m : hub.take_messages()) seen_.push_back(m);
          return seen(parts);
        },
        timeout_ms);
  }
  bool seen(std::initializer_list<const char*> parts) const {
    for (const auto& m : seen_) {
      bool all = true;
      for (const char* p : parts) all = all && m.find(p) != std::string::npos;
      if (all) return true;
    }
    return false;
  }
  std::vector<std::string> seen_;
};

bool connected(DeviceHub& hub, const std::string& slot) {
  for (const auto& d : hub.snapshot().devices)
    if (d.slot == slot) return d.connected;
  return false;
}

// 1. LeapPollConnection can block despite its timeout: stop() closes the connection first, which
// ends the poll, and never waits on it unbounded.
TEST_F(LeapcFinding, StopClosesTheConnectionBeforeJoiningSoABlockedPollCannotHangIt) {
  fake_leapc::block_polls(true, 1500);
  LeapcRig rig;
  DeviceHub& hub = rig.hub;
  std::this_thread::sleep_for(std::chrono::milliseconds(30));  // the poll thread is inside the blocked poll
  const auto t0 = std::chrono::steady_clock::now();
  hub.stop();
  const auto took = std::chrono::steady_clock::now() - t0;
  EXPECT_LT(took, std::chrono::milliseconds(500)) << "stop() waited for the blocked poll";
  EXPECT_EQ(fake_leapc::stats().connections_closed, 1);
}

// 2a. A re-plugged controller whose new Device event comes before the old DeviceLost is refused
// as a duplicate serial at first, and taken as soon as the holder goes.
TEST_F(LeapcFinding, ADuplicateRefusedIsTakenWhenTheDeviceHoldingItsSerialGoes) {
  LeapcRig rig;
  DeviceHub& hub = rig.hub;
  Recorded& rec = rig.rec;
  fake_leapc::plug(1, "LP22222");
  ASSERT_TRUE(wait_for([&] { return connected(hub, "LMC2"); }));
  fake_leapc::plug(2, "LP22222");  // the same controller, re-plugged, announced before it is lost
  ASSERT_TRUE(wait_message(hub, {"refused the controller with device id 2"}));
  fake_leapc::unplug(1);
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 2; })) << "never reconsidered";
  fake_leapc::track(2, 5, 100, 30.0F, {fake_leapc::make_hand(leapc::kHandRight, 2)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 1; }));
  EXPECT_TRUE(connected(hub, "LMC2"));
  hub.stop();
  EXPECT_EQ(rec.frames[0].device_id, 2);
}

// 2b. A service that restarts without a ConnectionLost sends a Connection event while devices are
// open: their handles are stale, so they are closed and the devices it announces again are taken.
TEST_F(LeapcFinding, AConnectionEventWithDevicesOpenResetsThem) {
  LeapcRig rig;
  DeviceHub& hub = rig.hub;
  fake_leapc::plug(1, "LP11111");
  ASSERT_TRUE(wait_for([&] { return connected(hub, "LMC1"); }));
  fake_leapc::connection_event(0);
  fake_leapc::plug(9, "LP11111");  // the restarted service numbers it afresh
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 2; })) << "refused as its own duplicate";
  ASSERT_TRUE(wait_for([&] { return connected(hub, "LMC1"); }));
  EXPECT_EQ(fake_leapc::stats().open_handles, 1) << "the stale handle was kept";
  hub.stop();
}

// 2c. A Device event for an id already open: the service re-enumerated it; the stale handle is
// closed and the device opened again.
TEST_F(LeapcFinding, ARepeatedDeviceEventForAnOpenIdReopensIt) {
  LeapcRig rig;
  DeviceHub& hub = rig.hub;
  fake_leapc::plug(1, "LP11111");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 1; }));
  fake_leapc::announce(1);
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 2; })) << "the repeated announcement was ignored";
  ASSERT_TRUE(wait_for([&] { return connected(hub, "LMC1"); }));
  EXPECT_EQ(fake_leapc::stats().open_handles, 1);
  hub.stop();
}

// 3. A serial that cannot be read (for a moment after a hot-plug) is a failed open, tried again;
// the controller then takes its own slot, never a placeholder key in the next free one.
TEST_F(LeapcFinding, AFailedSerialReadIsRetriedAndNeverGivesAPlaceholderSlot) {
  LeapcOptions o = test_options();
  o.retry_interval_ms = 5;
  LeapcRig rig(o);
  DeviceHub& hub = rig.hub;
  fake_leapc::fail_serial(3, 2);
  fake_leapc::plug(3, "LP33333");
  ASSERT_TRUE(wait_for([&] { return connected(hub, "LMC3"); }));
  hub.stop();
  for (const auto& [serial, slot] : hub.serial_to_slot()) {
    EXPECT_EQ(serial.find("leapc-id"), std::string::npos) << serial << " → " << slot;
    EXPECT_EQ(serial, "LP33333");
  }
  EXPECT_GE(fake_leapc::stats().open_attempts, 3);
}

// 4. Closing a device may free the message in hand (valid "until the connection or device is
// closed"): the message is done with before the housekeeping that closes devices runs.
TEST_F(LeapcFinding, NoMessageIsReadAfterHousekeepingClosesADevice) {
  LeapcOptions o = test_options();
  o.retry_interval_ms = 1;
  o.max_attempts = 3;
  LeapcRig rig(o);
  DeviceHub& hub = rig.hub;
  Recorded& rec = rig.rec;
  fake_leapc::plug(2, "LP22222");
  ASSERT_TRUE(wait_for([&] { return connected(hub, "LMC2"); }));
  // Device 1 opens but can never be subscribed: a retry gives up and closes it while device 2's
  // tracking messages keep arriving.
  fake_leapc::fail_subscribe(1, 1000);
  fake_leapc::plug(1, "LP11111");
  constexpr int kFrames = 200;
  for (int k = 0; k < kFrames; ++k)
    fake_leapc::track(2, 10 + k, 1000 + k, 30.0F, {fake_leapc::make_hand(leapc::kHandRight, 2)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == kFrames; }));
  ASSERT_TRUE(wait_message(hub, {"gave up after 3 attempts"}));
  hub.stop();
  for (int k = 0; k < kFrames; ++k) ASSERT_EQ(rec.frames[k].frame_id, 10 + k);
}

// 5. At connect the service sends the policies the device had (none) and a mode query answers with
// the old mode before the request takes effect: neither is a refusal or a wrong mode.
TEST_F(LeapcFinding, NoFalseRefusalOrWrongModeWarningAtStart) {
  LeapcOptions o = test_options();
  o.warning_grace_ms = 300;
  LeapcRig rig(o);
  DeviceHub& hub = rig.hub;
  fake_leapc::plug(1, "LP11111", fake_leapc::kPidPeripheral, leapc::kModeHmd);  // left head-mounted
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 1; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(450));
  for (auto& m : hub.take_messages()) seen_.push_back(m);
  hub.stop();
  EXPECT_FALSE(seen({"refused the background-frames policy"}));
  EXPECT_FALSE(seen({"not the desktop mode"}));
  EXPECT_EQ(fake_leapc::requested_tracking_mode(1), static_cast<int>(leapc::kModeDesktop));
  EXPECT_EQ(hub.snapshot().devices[0].tracking_mode, "desktop");
}

// 6. A frame the service drops is a DroppedFrame event and a gap in the image frame ids: one drop.
TEST_F(LeapcFinding, AFrameTheServiceDropsCountsOnce) {
  LeapcRig rig;
  DeviceHub& hub = rig.hub;
  Recorded& rec = rig.rec;
  fake_leapc::plug(1, "LP11111");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 1; }));
  fake_leapc::track(1, 10, 1000, 30.0F, {fake_leapc::make_hand(leapc::kHandRight, 1)});
  fake_leapc::dropped_frame(1, 11);
  fake_leapc::track(1, 12, 1066, 30.0F, {fake_leapc::make_hand(leapc::kHandRight, 1)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 2; }));
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().pending == 0; }));
  hub.stop();
  EXPECT_EQ(hub.snapshot().devices[0].frames_dropped, 1);
}

// 7. A service that is not running may leave every poll to time out: it is named all the same.
TEST_F(LeapcFinding, AServiceThatOnlyTimesOutIsNamedWithinSeconds) {
  fake_leapc::silent_service(true);
  LeapcRig rig;
  DeviceHub& hub = rig.hub;
  EXPECT_TRUE(wait_message(hub, {"waiting for the Ultraleap service", "not running"}, 2000));
  hub.stop();
}

// 8a. The service's log events reach the Devices tab's log (the hub's messages, and the sidecar).
TEST_F(LeapcFinding, TheServicesLogEventsAreShown) {
  LeapcRig rig;
  DeviceHub& hub = rig.hub;
  fake_leapc::log_event(leapc::kLogWarning, "camera 1 is running hot");
  EXPECT_TRUE(wait_message(hub, {"Ultraleap service (warning): camera 1 is running hot"}));
  hub.stop();
}

// 8b. Status and failure events of a device opened but not yet subscribed give it no Devices row.
TEST_F(LeapcFinding, ADeviceHasNoRowBeforeItIsSubscribed) {
  LeapcOptions o = test_options();
  o.retry_interval_ms = 200;
  LeapcRig rig(o);
  DeviceHub& hub = rig.hub;
  fake_leapc::fail_subscribe(1, 1);
  fake_leapc::plug(1, "LP11111");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribe_attempts == 1; }));
  fake_leapc::status_change(1, leapc::kStatusStreaming, leapc::kStatusStreaming | leapc::kStatusSmudged);
  fake_leapc::device_failure(1, leapc::kStatusBadTransport, /*with_handle=*/true);
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().pending == 0; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_TRUE(hub.snapshot().devices.empty()) << "a row before the device streams";
  ASSERT_TRUE(wait_for([&] { return connected(hub, "LMC1"); }));
  hub.stop();
}

struct NoSink final : FrameSink {
  void on_device_event(const DeviceEvent&) override {}
  void on_frame(const SourceFrame&) override {}
};

// 9. A thread switch between reading the host clock and LeapGetNow is an error of its own: the
// reading is the narrowest of several host/Leap/host brackets, its half-width the uncertainty.
TEST_F(LeapcFinding, TheDeviceClockIsReadInTheNarrowestOfSeveralBrackets) {
  fake_leapc::set_clock_offset_us(5'000'000'000);
  NoSink sink;
  LeapcSource source(test_options());
  source.start(sink);
  fake_leapc::slow_get_now(1, 20'000);  // the next LeapGetNow comes 20 ms late
  const std::int64_t before = fake_leapc::now_us();
  const std::int64_t host = host_now_ns();
  const std::int64_t after = fake_leapc::now_us();
  const std::optional<std::int64_t> read = source.device_clock_us(host);
  source.stop();
  ASSERT_TRUE(read.has_value());
  EXPECT_GE(*read, before - 1'000);
  EXPECT_LE(*read, after + 1'000) << "read " << (*read - after) << " µs late";
  ASSERT_TRUE(source.device_clock_uncertainty_us().has_value());
  EXPECT_GE(*source.device_clock_uncertainty_us(), 0);
  EXPECT_LT(*source.device_clock_uncertainty_us(), 1'000);
}

}  // namespace
}  // namespace lmc::devices
