// The LeapC backend against the LeapC test double: discovery, four serials → slots, interleaved
// tracking events, right-hand selection, a device lost mid-stream and coming back under a new id,
// failures, dropped frames, a lost service connection (devices/leapc/README.md).
#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "devices/device_hub.h"
#include "devices/leapc/leapc_source.h"
#include "fake_leapc.h"

namespace lmc::devices {
namespace {

bool wait_for(const std::function<bool()>& done, int timeout_ms = 3000) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

Layout layout_with_serials() {
  Layout l;
  l.name = "rig";
  const char* serials[] = {"LP11111", "LP22222", "LP33333", "LP44444"};
  for (int i = 0; i < 4; ++i) {
    LayoutDevice d;
    d.slot = "LMC" + std::to_string(i + 1);
    d.serial = serials[i];
    l.devices.push_back(d);
  }
  return l;
}

struct Recorded : FrameConsumer {
  std::mutex m;
  std::vector<HandFrame> frames;
  bool offer(const HandFrame& f, std::int64_t, bool) override {
    std::lock_guard lock(m);
    frames.push_back(f);
    return true;
  }
  void device_event(const DeviceEvent&, int, const std::string&) override {}
  size_t size() {
    std::lock_guard lock(m);
    return frames.size();
  }
};

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
  hub.add_source(std::make_unique<LeapcSource>());
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
    EXPECT_EQ(fake_leapc::device_policy(id) & eLeapPolicyFlag_BackgroundFrames,
              static_cast<std::uint64_t>(eLeapPolicyFlag_BackgroundFrames))
        << "device " << id;

  // Interleaved tracking: device id k sends hands whose palm encodes k.
  const std::uint32_t ids[] = {7, 3, 9, 4};
  for (int round = 0; round < 5; ++round)
    for (std::uint32_t id : ids)
      fake_leapc::track(id, 1000 + round, 2'000'000 + round * 30'000 + id, 30.0F,
                        {fake_leapc::make_hand(eLeapHandType_Left, 500), fake_leapc::make_hand(eLeapHandType_Right, 10.0F * id)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 20; }));
  hub.stop();
  EXPECT_EQ(fake_leapc::stats().concurrent_polls, 0);
  EXPECT_EQ(fake_leapc::stats().devices_closed, 4);

  // id → serial → slot: 3 → LP11111 → LMC1, 4 → LMC2, 7 → LMC3, 9 → LMC4.
  const std::map<int, float> palm_x_by_slot = {{1, 30.0F}, {2, 40.0F}, {3, 70.0F}, {4, 90.0F}};
  std::map<int, int> per_slot;
  for (const auto& f : rec.frames) {
    ASSERT_TRUE(f.hand_present);
    EXPECT_FLOAT_EQ(static_cast<float>(f.point(kPalm).x()), palm_x_by_slot.at(f.device_id)) << "the right hand, by hand type";
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

TEST_F(LeapcBackend, FrameWithoutTheWantedHandHasNoHand) {
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>());
  hub.start();
  fake_leapc::plug(1, "LP11111");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 1; }));
  fake_leapc::track(1, 1, 100, 0.0F, {fake_leapc::make_hand(eLeapHandType_Left, 5)});
  fake_leapc::track(1, 2, 200, 0.0F, {});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 2; }));
  hub.stop();
  EXPECT_FALSE(rec.frames[0].hand_present);
  EXPECT_FALSE(rec.frames[1].hand_present);
  EXPECT_EQ(rec.frames[1].timestamp_us, 200);
}

TEST_F(LeapcBackend, DeviceLostMidStreamAndBackUnderANewIdKeepsItsSlot) {
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>());
  hub.start();
  fake_leapc::plug(1, "LP11111");
  fake_leapc::plug(2, "LP22222");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 2; }));
  fake_leapc::track(1, 1, 100, 0, {fake_leapc::make_hand(eLeapHandType_Right, 1)});
  fake_leapc::track(2, 1, 110, 0, {fake_leapc::make_hand(eLeapHandType_Right, 2)});
  fake_leapc::unplug(2);
  // Frames the service still had queued for the lost device are not delivered to anyone.
  fake_leapc::track(2, 2, 150, 0, {fake_leapc::make_hand(eLeapHandType_Right, 2)});
  fake_leapc::track(1, 2, 160, 0, {fake_leapc::make_hand(eLeapHandType_Right, 1)});
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
  fake_leapc::track(12, 3, 300, 0, {fake_leapc::make_hand(eLeapHandType_Right, 2)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 4; }));
  hub.stop();
  EXPECT_EQ(rec.frames.back().device_id, 2);
  EXPECT_TRUE(hub.snapshot().devices[1].connected);
  EXPECT_EQ(hub.serial_to_slot().size(), 2u);
}

TEST_F(LeapcBackend, FailuresDropsAndServiceLossAreReported) {
  DeviceHub hub(layout_with_serials());
  hub.add_source(std::make_unique<LeapcSource>());
  hub.start();
  fake_leapc::plug(5, "LP33333");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 1; }));
  hub.take_messages();
  fake_leapc::device_failure(5, eLeapDeviceStatus_BadTransport);
  fake_leapc::status_change(5, eLeapDeviceStatus_Streaming, eLeapDeviceStatus_Streaming | eLeapDeviceStatus_Smudged);
  fake_leapc::dropped_frame(5, 77);
  fake_leapc::dropped_frame(5, 78);
  fake_leapc::connection_event(eLeapServiceState_LowFpsDetected);
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
  EXPECT_EQ(hub.snapshot().devices[0].frames_dropped, 2);
}

TEST_F(LeapcBackend, APolicyThatCannotBeSetIsReportedAndTheDeviceStillStreams) {
  DeviceHub hub(layout_with_serials());
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>());
  hub.start();
  fake_leapc::fail_policy_ex(2, eLeapRS_NotAvailable);
  fake_leapc::plug(1, "LP11111");
  fake_leapc::plug(2, "LP22222");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 2; }));
  fake_leapc::track(2, 1, 100, 0, {fake_leapc::make_hand(eLeapHandType_Right, 2)});
  ASSERT_TRUE(wait_for([&] { return rec.size() == 1; }));
  hub.stop();
  EXPECT_EQ(fake_leapc::stats().policy_ex_calls, 2);
  EXPECT_NE(fake_leapc::device_policy(1) & eLeapPolicyFlag_BackgroundFrames, 0u);
  EXPECT_EQ(fake_leapc::device_policy(2), 0u);
  bool told = false;
  for (const auto& m : hub.take_messages())
    told = told || (m.find("LP22222") != std::string::npos && m.find("background-frames policy") != std::string::npos &&
                    m.find("eLeapRS_NotAvailable") != std::string::npos);
  EXPECT_TRUE(told);
}

TEST_F(LeapcBackend, DeviceFailureIsMatchedByItsDeviceHandle) {
  DeviceHub hub(layout_with_serials());
  hub.add_source(std::make_unique<LeapcSource>());
  hub.start();
  fake_leapc::plug(5, "LP33333");
  fake_leapc::plug(6, "LP44444");
  ASSERT_TRUE(wait_for([&] { return fake_leapc::stats().subscribed == 2; }));
  hub.take_messages();
  // No device id on the message: only the event's hDevice says which controller failed.
  fake_leapc::device_failure(6, eLeapDeviceStatus_BadTransport, /*with_handle=*/true, /*with_message_device_id=*/false);
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

TEST(LeapcNames, ResultAndStatusText) {
  EXPECT_EQ(leapc_result_name(eLeapRS_Timeout), "eLeapRS_Timeout");
  EXPECT_EQ(leapc_result_name(0xE2019999u), "eLeapRS 0xE2019999");
  EXPECT_EQ(leapc_status_text(eLeapDeviceStatus_Streaming | eLeapDeviceStatus_LowResource), "streaming low resource");
  EXPECT_NE(leapc_status_text(eLeapDeviceStatus_BadTransport).find("USB"), std::string::npos);
}

}  // namespace
}  // namespace lmc::devices
