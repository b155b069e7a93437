// The LeapC backend against the LeapC test double: discovery, four serials → slots, interleaved
// tracking events, right-hand selection and the other side's only hand, a device lost mid-stream
// and coming back under a new id, failures, dropped frames summed per second, a lost service
// connection, a service not up yet, tracking modes and policies answered asynchronously, product
// ids, the study's frame ids, duplicate serials, retried opens and subscribes, the device clock.
#include <chrono>
#include <functional>
#include <initializer_list>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/io/sensor_catalogue_json.h"
#include "devices/device_hub.h"
#include "devices/leapc/leapc_source.h"
#include "devices/record/clock_alignment.h"
#include "fake_leapc.h"
#include "leapc_test_support.h"

namespace lmc::devices {
namespace {

bool has_message(const std::vector<std::string>& messages, std::initializer_list<const char*> parts) {
  for (const auto& m : messages) {
    bool all = true;
    for (const char* p : parts) all = all && m.find(p) != std::string::npos;
    if (all) return true;
  }
  return false;
}

// Every message the hub has had, gathered until `parts` all appear in one (or the time is up).
bool wait_for_message(DeviceHub& hub, std::vector<std::string>& seen, std::initializer_list<const char*> parts) {
  return wait_for([&] {
    for (auto& m : hub.take_messages()) seen.push_back(m);
    return has_message(seen, parts);
  });
}

class LeapcBackend : public ::testing::Test {
 protected:
  void SetUp() override { fake_leapc::reset(); }
  void TearDown() override { fake_leapc::reset(); }
  static size_t drained() { return static_cast<size_t>(fake_leapc::stats().pending); }
};

TEST_F(LeapcBackend, FourDevicesAreDiscoveredSubscribedAndMappedBySerial) {
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  // The service announces them in another order and with its own ids.
  fake_leapc::plug(7, "LP33333");
  fake_leapc::plug(3, "LP11111");
  fake_leapc::plug(9, "LP44444");
  fake_leapc::plug(4, "LP22222");
  ASSERT_TRUE(wait_for([&] { return hub.serial_to_slot().size() == 4; }));
  const auto st = fake_leapc::stats();
  EXPECT_EQ(st.multi_device_aware, 1);
  EXPECT_EQ(st.devices_opened, 4);
  EXPECT_EQ(st.subscribed, 4);
  // Background frames are requested per device (LeapSetPolicyFlagsEx): the connection-wide
  // LeapSetPolicyFlags would reach only the primary device.
  EXPECT_EQ(st.policy_ex_calls, 4);
  for (const std::uint32_t id : {7u, 3u, 9u, 4u})
    EXPECT_EQ(fake_leapc::device_policy(id) & leapc::kPolicyBackgroundFrames,
              static_cast<std::uint64_t>(leapc::kPolicyBackgroundFrames))
        << "device " << id;

  // Interleaved tracking: device id k sends hands whose palm encodes k.
  const std::uint32_t ids[] = {7, 3, 9, 4};
  for (int round = 0; round < 5; ++round)
    for (std::uint32_t id : ids)
      fake_leapc::track(
          id, 1000 + round, 2'000'000 + round * 30'000 + id, 30.0F,
          {fake_leapc::make_hand(leapc::kHandLeft, 500), fake_leapc::make_hand(leapc::kHandRight, 10.0F * id)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 20; }));
  hub.stop();
  EXPECT_EQ(fake_leapc::stats().concurrent_polls, 0);
  EXPECT_EQ(fake_leapc::stats().devices_closed, 4);

  // id → serial → slot: 3 → LP11111 → LMC1, 4 → LMC2, 7 → LMC3, 9 → LMC4.
  const std::map<int, float> palm_x_by_slot = {{1, 30.0F}, {2, 40.0F}, {3, 70.0F}, {4, 90.0F}};
  std::map<int, int> per_slot;
  for (const auto& f : rec.frames) {
    ASSERT_TRUE(f.hand_present);
    EXPECT_FLOAT_EQ(static_cast<float>(f.point(kPalm).x()), palm_x_by_slot.at(f.device_id))
        << "the right hand, by hand type";
    // The 28 points come from the documented bones: elbow = arm.prev_joint, wrist = arm.next_joint,
    // digit joints = bones[0].prev_joint then bones[0..3].next_joint.
    const double base = palm_x_by_slot.at(f.device_id);
    EXPECT_DOUBLE_EQ(f.point(kElbow).x(), base + 1);
    EXPECT_DOUBLE_EQ(f.point(kWrist).x(), base + 2);
    EXPECT_DOUBLE_EQ(f.point(Digit::kMiddle, Joint::kMeta).x(), base + 3 + 10);
    EXPECT_DOUBLE_EQ(f.point(Digit::kMiddle, Joint::kEnd).x(), base + 3 + 10 + 4);
    EXPECT_DOUBLE_EQ(f.point(kPalmNormal).y(), -1.0);
    EXPECT_EQ(f.frame_rate_hz, 30.0);
    ++per_slot[f.device_id];
  }
  for (int slot = 1; slot <= 4; ++slot) EXPECT_EQ(per_slot[slot], 5);
}

TEST_F(LeapcBackend, TheOnlyHandOfTheOtherSideIsKeptAndCounted) {
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::plug(1, "LP11111");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 1; }));
  // The subject's right hand misclassified as left, alone in view: kept, marked.
  fake_leapc::track(1, 1, 100, 0.0F, {fake_leapc::make_hand(leapc::kHandLeft, 5)});
  // Both sides in view: the right one, nothing to count.
  fake_leapc::track(1, 2, 200, 0.0F,
                    {fake_leapc::make_hand(leapc::kHandLeft, 7), fake_leapc::make_hand(leapc::kHandRight, 9)});
  // Two hands, both left: which one is the subject's is anyone's guess, so no hand.
  fake_leapc::track(1, 3, 300, 0.0F,
                    {fake_leapc::make_hand(leapc::kHandLeft, 11), fake_leapc::make_hand(leapc::kHandLeft, 13)});
  fake_leapc::track(1, 4, 400, 0.0F, {});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 4; }));
  hub.stop();
  ASSERT_TRUE(rec.frames[0].hand_present);
  EXPECT_DOUBLE_EQ(rec.frames[0].point(kPalm).x(), 5.0);
  ASSERT_TRUE(rec.frames[1].hand_present);
  EXPECT_DOUBLE_EQ(rec.frames[1].point(kPalm).x(), 9.0);
  EXPECT_FALSE(rec.frames[2].hand_present);
  EXPECT_FALSE(rec.frames[3].hand_present);
  EXPECT_EQ(rec.frames[3].timestamp_us, 400);
  EXPECT_EQ(rec.other_side, std::vector<int>{1});  // one frame, of LMC1
  EXPECT_EQ(hub.snapshot().devices[0].frames_other_side_hand, 1);
}

TEST_F(LeapcBackend, DeviceLostMidStreamAndBackUnderANewIdKeepsItsSlot) {
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::plug(1, "LP11111");
  fake_leapc::plug(2, "LP22222");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 2; }));
  fake_leapc::track(1, 1, 100, 0, {fake_leapc::make_hand(leapc::kHandRight, 1)});
  fake_leapc::track(2, 1, 110, 0, {fake_leapc::make_hand(leapc::kHandRight, 2)});
  fake_leapc::unplug(2);
  // Frames the service still had queued for the lost device are not delivered to anyone.
  fake_leapc::track(2, 2, 150, 0, {fake_leapc::make_hand(leapc::kHandRight, 2)});
  fake_leapc::track(1, 2, 160, 0, {fake_leapc::make_hand(leapc::kHandRight, 1)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 3 && drained() == 0; }));
  auto snap = hub.snapshot();
  EXPECT_FALSE(snap.devices[1].connected);
  EXPECT_EQ(snap.devices[1].disconnects, 1);
  bool told = false;
  for (const auto& m : hub.take_messages()) told = told || m == "LMC2 (LP22222) disconnected: device lost";
  EXPECT_TRUE(told);
  EXPECT_EQ(fake_leapc::stats().unsubscribed, 1);
  EXPECT_EQ(fake_leapc::stats().devices_closed, 1);

  fake_leapc::plug(12, "LP22222");  // re-plugged: a new id, the same serial
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 3; }));
  fake_leapc::track(12, 3, 300, 0, {fake_leapc::make_hand(leapc::kHandRight, 2)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 4; }));
  hub.stop();
  EXPECT_EQ(rec.frames.back().device_id, 2);
  EXPECT_TRUE(hub.snapshot().devices[1].connected);
  EXPECT_EQ(hub.serial_to_slot().size(), 2u);
}

TEST_F(LeapcBackend, FailuresDropsAndServiceLossAreReported) {
  DeviceHub hub(layout_with_serials());
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::plug(5, "LP33333");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 1; }));
  hub.take_messages();
  fake_leapc::device_failure(5, leapc::kStatusBadTransport);
  fake_leapc::status_change(5, leapc::kStatusStreaming, leapc::kStatusStreaming | leapc::kStatusSmudged);
  fake_leapc::dropped_frame(5, 77);
  fake_leapc::dropped_frame(5, 78);
  fake_leapc::connection_event(leapc::kServiceLowFps);
  fake_leapc::connection_lost();
  ASSERT_TRUE(wait_for([&] { return drained() == 0 && !hub.snapshot().devices[0].connected; }));
  const auto msgs = hub.take_messages();
  // When the service is back it announces the device again: the backend reopens and resubscribes.
  fake_leapc::plug(5, "LP33333");
  ASSERT_TRUE(wait_for([&] { return hub.snapshot().devices[0].connected; }));
  EXPECT_EQ(fake_leapc::stats().subscribed, 2);
  EXPECT_EQ(hub.snapshot().devices[0].slot, "LMC3");
  hub.stop();
  auto has = [&](const std::string& text) {
    for (const auto& m : msgs)
      if (m.find(text) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(has("LMC3 (LP33333) failure: bad transport"));
  EXPECT_TRUE(has("smudged"));
  EXPECT_TRUE(has("low frame rate detected"));
  EXPECT_TRUE(has("connection to the Ultraleap service lost"));
  // Said, not counted: the frames the service dropped are gaps in the frame ids, counted there.
  EXPECT_TRUE(has("the service dropped 1 frame"));
  EXPECT_EQ(hub.snapshot().devices[0].frames_dropped, 0);
}

TEST_F(LeapcBackend, APolicyThatCannotBeSetIsReportedAndTheDeviceStillStreams) {
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::fail_policy_ex(2, leapc::kNotAvailable);
  fake_leapc::plug(1, "LP11111");
  fake_leapc::plug(2, "LP22222");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 2; }));
  fake_leapc::track(2, 1, 100, 0, {fake_leapc::make_hand(leapc::kHandRight, 2)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 1; }));
  hub.stop();
  EXPECT_EQ(fake_leapc::stats().policy_ex_calls, 2);
  EXPECT_NE(fake_leapc::device_policy(1) & leapc::kPolicyBackgroundFrames, 0u);
  EXPECT_EQ(fake_leapc::device_policy(2), 0u);
  bool told = false;
  for (const auto& m : hub.take_messages())
    told = told || (m.find("LP22222") != std::string::npos && m.find("background-frames policy") != std::string::npos &&
                    m.find("eLeapRS_NotAvailable") != std::string::npos);
  EXPECT_TRUE(told);
}

TEST_F(LeapcBackend, DeviceFailureIsMatchedByItsDeviceHandle) {
  DeviceHub hub(layout_with_serials());
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::plug(5, "LP33333");
  fake_leapc::plug(6, "LP44444");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 2; }));
  hub.take_messages();
  // No device id on the message: only the event's hDevice says which controller failed.
  fake_leapc::device_failure(6, leapc::kStatusBadTransport, /*with_handle=*/true, /*with_message_device_id=*/false);
  ASSERT_TRUE(wait_for([&] { return drained() == 0; }));
  std::vector<std::string> msgs;
  ASSERT_TRUE(wait_for([&] {
    for (auto& m : hub.take_messages()) msgs.push_back(m);
    return !msgs.empty();
  }));
  hub.stop();
  bool found = false;
  for (const auto& m : msgs) found = found || m.find("LMC4 (LP44444) failure: bad transport") != std::string::npos;
  EXPECT_TRUE(found) << (msgs.empty() ? std::string("no message") : msgs.front());
}

TEST_F(LeapcBackend, EachDeviceIsAskedForTheTrackingModeOfItsPlaceAndItsModeAndModelAreShown) {
  Layout l = layout_with_serials();
  l.devices[0].pose.rx_deg = 180;  // LMC1 hangs above the hand, looking down
  LeapcOptions o = test_options();
  o.layout = l;
  DeviceHub hub(l);
  hub.add_source(std::make_unique<LeapcSource>(o));
  hub.start();
  // Both left in head-mounted mode by another program; LMC2 is a Leap Motion Controller 2.
  fake_leapc::plug(1, "LP11111", fake_leapc::kPidPeripheral, leapc::kModeHmd);
  fake_leapc::plug(2, "LP22222", fake_leapc::kPidLmc2, leapc::kModeHmd);
  // The service applies a request a few polls later (the double as well), and a read before then
  // gives the old mode: the Devices row may show head-mounted first. Waited for until both show
  // the mode of their place; a backend that never got there fails here.
  auto modes_settled = [&] {
    const auto snap = hub.snapshot();
    return snap.devices.size() == 2 && snap.devices[0].tracking_mode == "screen-top" &&
           snap.devices[1].tracking_mode == "desktop";
  };
  ASSERT_TRUE(wait_for(modes_settled)) << "modes shown: " << [&] {
    std::string shown;
    for (const auto& d : hub.snapshot().devices) shown += d.slot + " " + d.tracking_mode + "; ";
    return shown;
  }();
  EXPECT_EQ(fake_leapc::requested_tracking_mode(1), leapc::kModeScreenTop);
  EXPECT_EQ(fake_leapc::requested_tracking_mode(2), leapc::kModeDesktop);
  EXPECT_EQ(fake_leapc::stats().tracking_mode_calls, 2);
  EXPECT_EQ(fake_leapc::stats().tracking_mode_queries, 2);
  const auto snap = hub.snapshot();
  EXPECT_EQ(snap.devices[0].slot, "LMC1");
  EXPECT_EQ(snap.devices[0].model, "Leap Motion Controller");
  EXPECT_EQ(snap.devices[0].tracking_mode, "screen-top");
  EXPECT_EQ(snap.devices[1].slot, "LMC2");
  EXPECT_EQ(snap.devices[1].model, "Leap Motion Controller 2");
  EXPECT_EQ(snap.devices[1].tracking_mode, "desktop");

  // The control panel switches LMC2 to head-mounted mid-session: reported, shown.
  std::vector<std::string> seen;
  fake_leapc::change_tracking_mode(2, leapc::kModeHmd);
  ASSERT_TRUE(wait_for_message(hub, seen, {"LMC2 (LP22222) tracks in head-mounted mode", "not the desktop mode"}));
  EXPECT_EQ(hub.snapshot().devices[1].tracking_mode, "head-mounted");
  hub.stop();
}

// A slot laid out as one model with another model connected: the hub warns and the Devices tab
// shows it; the slot of the right model stays quiet.
TEST_F(LeapcBackend, AControllerOfAnotherModelThanItsSlotGetsAWarning) {
  Layout l = layout_with_serials();
  l.devices.resize(2);
  set_device_model(l.devices[0], sensor_catalogue().at("lmc", "test"));
  set_device_model(l.devices[1], sensor_catalogue().at("lmc", "test"));
  DeviceHub hub(l);
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::plug(1, "LP11111", fake_leapc::kPidPeripheral);
  fake_leapc::plug(2, "LP22222", fake_leapc::kPidLmc2);
  std::vector<std::string> seen;
  ASSERT_TRUE(wait_for_message(
      hub, seen,
      {"warning: LMC2 is laid out as a Leap Motion Controller (lmc) but a Leap Motion Controller 2 (lmc2)"}));
  const auto snap = hub.snapshot();
  ASSERT_EQ(snap.devices.size(), 2u);
  EXPECT_EQ(snap.devices[0].product_id, static_cast<std::uint32_t>(fake_leapc::kPidPeripheral));
  EXPECT_EQ(snap.devices[0].model_warning, "");
  EXPECT_EQ(snap.devices[1].product_id, static_cast<std::uint32_t>(fake_leapc::kPidLmc2));
  EXPECT_NE(snap.devices[1].model_warning.find("change the slot's model"), std::string::npos);
  hub.stop();
}

TEST_F(LeapcBackend, AModeTheServiceKeepsIsReportedAsWrong) {
  DeviceHub hub(layout_with_serials());
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::hold_tracking_mode(3, leapc::kModeScreenTop);
  fake_leapc::plug(3, "LP33333");
  std::vector<std::string> seen;
  ASSERT_TRUE(wait_for_message(hub, seen, {"LMC3 (LP33333) tracks in screen-top mode", "not the desktop mode"}));
  EXPECT_EQ(hub.snapshot().devices[0].tracking_mode, "screen-top");
  hub.stop();
}

TEST_F(LeapcBackend, AListingLearnsEachModeWithoutChangingIt) {
  LeapcOptions o = test_options();
  o.request_tracking_mode = false;  // as `lmc devices` runs it
  DeviceHub hub(layout_with_serials());
  hub.add_source(std::make_unique<LeapcSource>(o));
  hub.start();
  fake_leapc::plug(4, "LP44444", fake_leapc::kPidSir170, leapc::kModeHmd);
  ASSERT_TRUE(wait_for([&] {
    const auto snap = hub.snapshot();
    return snap.devices.size() == 1 && !snap.devices[0].tracking_mode.empty();
  }));
  const auto snap = hub.snapshot();
  hub.stop();
  EXPECT_EQ(fake_leapc::requested_tracking_mode(4), -1);
  EXPECT_EQ(snap.devices[0].tracking_mode, "head-mounted");
  EXPECT_EQ(snap.devices[0].model, "Stereo IR 170");
}

TEST_F(LeapcBackend, APolicyTheServiceRefusesIsReported) {
  DeviceHub hub(layout_with_serials());
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  // The request is accepted; the answer (a Policy event) comes later without the flag.
  fake_leapc::refuse_policy(2, leapc::kPolicyBackgroundFrames);
  fake_leapc::plug(1, "LP11111");
  fake_leapc::plug(2, "LP22222");
  std::vector<std::string> seen;
  ASSERT_TRUE(wait_for_message(hub, seen, {"LMC2 (LP22222)", "refused the background-frames policy"}));
  ASSERT_TRUE(wait_for([&] { return drained() == 0; }));
  for (auto& m : hub.take_messages()) seen.push_back(m);
  hub.stop();
  EXPECT_FALSE(has_message(seen, {"LP11111", "refused"}));
  EXPECT_EQ(fake_leapc::stats().policy_ex_calls, 2);
}

TEST_F(LeapcBackend, FramesCarryTheServicesImageFrameIdAsTheStudysFilesDo) {
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::plug(1, "LP11111");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 1; }));
  // The service dropped images 5001 and 5002: info.frame_id skips, tracking_frame_id (1, 2) does not.
  fake_leapc::track(1, 5000, 100, 30.0F, {fake_leapc::make_hand(leapc::kHandRight, 1)});
  fake_leapc::track(1, 5003, 200, 30.0F, {fake_leapc::make_hand(leapc::kHandRight, 1)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 2; }));
  hub.stop();
  EXPECT_EQ(rec.frames[0].frame_id, 5000);
  EXPECT_EQ(rec.frames[1].frame_id, 5003);
  EXPECT_EQ(hub.snapshot().devices[0].frames_dropped, 2);
}

TEST_F(LeapcBackend, TwoDevicesWithOneSerialAreNeverMixedInOneSlot) {
  Layout l = layout_with_serials();
  l.devices[0].serial.reset();  // LMC1 takes whichever controller comes first
  DeviceHub hub(l);
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  // A service before 5.4 gives placeholders instead of serials.
  fake_leapc::plug(1, "device_1");
  fake_leapc::plug(2, "device_1");
  std::vector<std::string> seen;
  ASSERT_TRUE(wait_for_message(
      hub, seen, {"refused the controller with device id 2", "device_1", "update the Ultraleap service"}));
  fake_leapc::track(1, 1, 100, 0, {fake_leapc::make_hand(leapc::kHandRight, 1)});
  fake_leapc::track(2, 1, 105, 0, {fake_leapc::make_hand(leapc::kHandRight, 2)});
  fake_leapc::track(1, 2, 130, 0, {fake_leapc::make_hand(leapc::kHandRight, 1)});
  ASSERT_TRUE(wait_for([&] { return drained() == 0 && rec.size() == 2; }));
  hub.stop();
  EXPECT_EQ(fake_leapc::stats().subscribed, 1);
  EXPECT_EQ(fake_leapc::stats().tracking_suppressed, 1);
  EXPECT_EQ(hub.serial_to_slot().size(), 1u);
  for (const auto& f : rec.frames) EXPECT_DOUBLE_EQ(f.point(kPalm).x(), 1.0) << "only device 1's hand";
}

TEST_F(LeapcBackend, AFailedOpenOrSubscribeIsRetriedAndANeverSubscribedDeviceIsNotConnected) {
  LeapcOptions o = test_options();
  o.retry_interval_ms = 10;
  o.max_attempts = 4;
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>(o));
  hub.start();
  fake_leapc::fail_open(1, 2);
  fake_leapc::fail_subscribe(2, 2);
  fake_leapc::fail_subscribe(3, 100);  // never
  fake_leapc::plug(1, "LP11111");
  fake_leapc::plug(2, "LP22222");
  fake_leapc::plug(3, "LP33333");
  std::vector<std::string> seen;
  ASSERT_TRUE(wait_for_message(hub, seen, {"LP33333", "gave up after 4 attempts"}));
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 2; }));
  fake_leapc::track(1, 1, 100, 0, {fake_leapc::make_hand(leapc::kHandRight, 1)});
  fake_leapc::track(2, 1, 100, 0, {fake_leapc::make_hand(leapc::kHandRight, 2)});
  fake_leapc::track(3, 1, 100, 0, {fake_leapc::make_hand(leapc::kHandRight, 3)});
  ASSERT_TRUE(wait_for([&] { return drained() == 0 && rec.size() == 2; }));
  const auto snap = hub.snapshot();
  hub.stop();
  const auto st = fake_leapc::stats();
  EXPECT_EQ(st.open_attempts, 3 + 1 + 1);
  EXPECT_EQ(st.subscribe_attempts, 1 + 3 + 4);
  EXPECT_TRUE(has_message(seen, {"cannot open device 1", "trying again"}));
  ASSERT_EQ(snap.devices.size(), 2u) << "LP33333 never subscribed: not shown";
  for (const auto& d : snap.devices) {
    EXPECT_TRUE(d.connected) << d.serial;
    EXPECT_NE(d.serial, "LP33333");
  }
  EXPECT_EQ(st.devices_closed, 3) << "the one given up on is closed at once, the two others at stop";
}

TEST_F(LeapcBackend, AServiceNotRunningYetIsWaitedFor) {
  fake_leapc::not_connected_polls(5);
  DeviceHub hub(layout_with_serials());
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::plug(1, "LP11111");
  ASSERT_TRUE(wait_for([&] { return hub.snapshot().devices.size() == 1 && hub.snapshot().devices[0].connected; }));
  std::vector<std::string> seen;
  ASSERT_TRUE(wait_for_message(hub, seen, {"connected to the Ultraleap service"}));
  hub.stop();
  int waiting = 0;
  for (const auto& m : seen)
    waiting += m.find("waiting for the Ultraleap service (LeapC: eLeapRS_NotConnected)") != std::string::npos;
  EXPECT_EQ(waiting, 1) << "said once, not once per poll";
}

TEST_F(LeapcBackend, DroppedFramesAreSummedPerDeviceAndSecond) {
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::plug(1, "LP11111");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 1; }));
  for (int k = 0; k < 300; ++k) fake_leapc::dropped_frame(1, 100 + k);
  ASSERT_TRUE(wait_for([&] { return drained() == 0; }));
  hub.stop();  // what is still pending is said at the stop, never lost
  int events = 0;
  std::int64_t total = 0;
  for (const auto& e : rec.events) {
    const auto at = e.message.find("the service dropped ");
    if (at == std::string::npos) continue;
    ++events;
    total += std::stoll(e.message.substr(at + 20));
    EXPECT_EQ(e.info.serial, "LP11111");
    EXPECT_EQ(e.count, 0) << "said, not counted twice";
  }
  EXPECT_EQ(total, 300);
  EXPECT_LE(events, 3) << "one message per second at most, not one per frame";
}

TEST_F(LeapcBackend, TheDeviceClockAtAViconEventIsReadNotExtrapolatedFromTheLatestFrame) {
  fake_leapc::set_clock_offset_us(7'000'000'000);  // the Leap clock's epoch is its own
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  fake_leapc::plug(1, "LP11111");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 1; }));
  // Captured 40 ms before the service hands it over.
  const std::int64_t latency_us = 40'000;
  fake_leapc::track(1, 1, fake_leapc::now_us() - latency_us, 30.0F, {fake_leapc::make_hand(leapc::kHandRight, 1)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 1; }));
  const std::int64_t before_us = fake_leapc::now_us();
  const HubSnapshot snap = hub.snapshot();
  const std::int64_t after_us = fake_leapc::now_us();
  hub.stop();
  ASSERT_EQ(snap.devices.size(), 1u);
  ASSERT_TRUE(snap.devices[0].device_clock_us.has_value());
  EXPECT_GE(*snap.devices[0].device_clock_us, before_us);
  EXPECT_LE(*snap.devices[0].device_clock_us, after_us);

  // Vicon started 2 ms after the snapshot.
  const auto j = clock_alignment_json(snap, "CaptureStart sent", snap.host_time_ns + 2'000'000, 1, "");
  const auto& d = j["devices"][0];
  EXPECT_EQ(d["device_clock_method"], "read");
  EXPECT_EQ(d["device_clock_at_event_us"].get<std::int64_t>(), *snap.devices[0].device_clock_us + 2'000);
  // The sidecar says how far the read itself may be off: half its narrowest host bracket.
  ASSERT_TRUE(snap.devices[0].device_clock_uncertainty_us.has_value());
  EXPECT_EQ(d["device_clock_uncertainty_us"].get<std::int64_t>(), *snap.devices[0].device_clock_uncertainty_us);
  EXPECT_GE(d["device_clock_uncertainty_us"].get<std::int64_t>(), 0);
  EXPECT_LT(d["device_clock_uncertainty_us"].get<std::int64_t>(), 1'000);
  // The old estimate runs late by the latest frame's delivery latency (40 ms, plus however long
  // the poll thread took to pick it up); that latency is kept beside it.
  const std::int64_t late_by =
      d["device_clock_at_event_us"].get<std::int64_t>() - d["device_clock_extrapolated_us"].get<std::int64_t>();
  EXPECT_GE(late_by, latency_us - 1);
  EXPECT_LT(late_by, latency_us + 2'000'000);
  EXPECT_NEAR(static_cast<double>(d["latest_frame_latency_us"].get<std::int64_t>()), static_cast<double>(late_by), 1.0);
}

TEST(LeapcNames, ModelOfEachProductId) {
  EXPECT_EQ(leapc_model_name(fake_leapc::kPidPeripheral), "Leap Motion Controller");
  EXPECT_EQ(leapc_model_name(fake_leapc::kPidLmc2), "Leap Motion Controller 2");
  EXPECT_EQ(leapc_model_name(fake_leapc::kPidSir170), "Stereo IR 170");
  EXPECT_EQ(leapc_model_name(0x1234), "Ultraleap device (product id 0x1234)");
}

TEST(LeapcNames, ResultAndStatusText) {
  EXPECT_EQ(leapc_result_name(leapc::kTimeout), "eLeapRS_Timeout");
  EXPECT_EQ(leapc_result_name(0xE2019999u), "eLeapRS 0xE2019999");
  EXPECT_EQ(leapc_status_text(leapc::kStatusStreaming | leapc::kStatusLowResource), "streaming low resource");
  EXPECT_NE(leapc_status_text(leapc::kStatusBadTransport).find("USB"), std::string::npos);
}

}  // namespace
}  // namespace lmc::devices
