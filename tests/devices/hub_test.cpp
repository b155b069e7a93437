// Device hub: serial → slot mapping, statistics, snapshots, fan-out.
#include <gtest/gtest.h>
#include <atomic>

#include "devices/device_hub.h"

namespace lmc::devices {
namespace {

Layout four_slots(std::optional<std::string> lmc3_serial = std::nullopt) {
  Layout l;
  l.name = "test";
  for (int i = 1; i <= 4; ++i) {
    LayoutDevice d;
    d.slot = "LMC" + std::to_string(i);
    d.pose.x_mm = 10.0 * i;
    l.devices.push_back(d);
  }
  l.devices[2].serial = lmc3_serial;
  return l;
}

DeviceEvent appeared(const std::string& serial) {
  DeviceEvent e;
  e.kind = DeviceEventKind::kAppeared;
  e.info = {serial, "test", "fake", ""};
  return e;
}

SourceFrame frame(const std::string& serial, std::int64_t id, std::int64_t host_ns, bool hand = true) {
  SourceFrame f;
  f.serial = serial;
  f.frame.frame_id = id;
  f.frame.timestamp_us = host_ns / 1000;
  f.frame.hand_present = hand;
  f.host_receive_ns = host_ns;
  f.hand_type = HandType::kRight;
  return f;
}

struct CollectingConsumer : FrameConsumer {
  std::vector<HandFrame> frames;
  std::vector<std::pair<int, DeviceEventKind>> events;
  bool accept = true;
  bool offer(const HandFrame& f, std::int64_t, bool) override {
    if (accept) frames.push_back(f);
    return accept;
  }
  void device_event(const DeviceEvent& e, int id, const std::string&) override { events.emplace_back(id, e.kind); }
};

TEST(DeviceHub, BoundSerialGoesToItsSlotOthersFillFreeSlotsInOrder) {
  DeviceHub hub(four_slots("LP-333"));
  hub.on_device_event(appeared("A1"));
  hub.on_device_event(appeared("LP-333"));
  hub.on_device_event(appeared("B2"));
  const auto map = hub.serial_to_slot();
  ASSERT_EQ(map.size(), 3u);
  EXPECT_EQ(map[0], (std::pair<std::string, std::string>{"A1", "LMC1"}));
  EXPECT_EQ(map[1], (std::pair<std::string, std::string>{"B2", "LMC2"}));
  EXPECT_EQ(map[2], (std::pair<std::string, std::string>{"LP-333", "LMC3"}));
  // The guessed slots are announced as guesses; the bound serial is not.
  std::string guessed;
  for (const auto& m : hub.take_messages()) {
    if (m.find("order of appearance") != std::string::npos) guessed += m + "\n";
  }
  EXPECT_NE(guessed.find("A1"), std::string::npos) << guessed;
  EXPECT_NE(guessed.find("B2"), std::string::npos) << guessed;
  EXPECT_EQ(guessed.find("LP-333"), std::string::npos) << guessed;
}

TEST(DeviceHub, UnknownSerialsAreListedForAssignmentWhenAutoAssignIsOff) {
  HubOptions o;
  o.auto_assign = false;
  DeviceHub hub(four_slots("LP-333"), o);
  CollectingConsumer c;
  hub.set_consumer(&c);
  hub.on_device_event(appeared("X9"));
  hub.on_frame(frame("X9", 1, 1000));
  auto snap = hub.snapshot();
  ASSERT_EQ(snap.unassigned_serials, std::vector<std::string>{"X9"});
  EXPECT_TRUE(c.frames.empty()) << "an unassigned device must never be recorded into a slot";
  bool told = false;
  for (const auto& m : hub.take_messages()) told = told || m.find("assign it to a slot") != std::string::npos;
  EXPECT_TRUE(told);

  EXPECT_NE(hub.assign("X9", "LMC9"), "");
  EXPECT_NE(hub.assign("nobody", "LMC1"), "");
  EXPECT_EQ(hub.assign("X9", "LMC2"), "");
  hub.on_frame(frame("X9", 2, 2000));
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.frames[0].device_id, 2);
  snap = hub.snapshot();
  EXPECT_TRUE(snap.unassigned_serials.empty());
  EXPECT_EQ(snap.devices[0].slot, "LMC2");
  EXPECT_EQ(hub.layout().devices[1].serial, std::optional<std::string>("X9"));
}

TEST(DeviceHub, ReassigningASlotUnassignsItsPreviousDevice) {
  DeviceHub hub(four_slots());
  hub.on_device_event(appeared("A"));
  hub.on_device_event(appeared("B"));
  EXPECT_EQ(hub.assign("B", "LMC1"), "");
  auto snap = hub.snapshot();
  ASSERT_EQ(snap.unassigned_serials, std::vector<std::string>{"A"});
}

TEST(DeviceHub, RateIsFramesInTheLastSecondAndAgeComesFromTheClock) {
  std::atomic<std::int64_t> now{0};
  HubOptions o;
  o.clock = [&] { return now.load(); };
  DeviceHub hub(four_slots(), o);
  hub.on_device_event(appeared("A"));
  // 30 frames over 1.5 s (every 50 ms): the last second holds 20 of them (t = 0.55 … 1.5 s).
  for (int i = 0; i < 30; ++i) hub.on_frame(frame("A", 100 + i, (i + 1) * 50'000'000LL));
  now = 1'500'000'000LL + 10'000'000LL;
  const auto snap = hub.snapshot();
  ASSERT_EQ(snap.devices.size(), 1u);
  const DeviceStatus& s = snap.devices[0];
  EXPECT_DOUBLE_EQ(s.rate_hz, 20.0);
  EXPECT_NEAR(s.latest_frame_age_ms, 10.0, 1e-9);
  EXPECT_EQ(s.frames_received, 30);
  EXPECT_TRUE(s.hand_present);
  EXPECT_EQ(s.hand_type, HandType::kRight);
  ASSERT_TRUE(s.latest.has_value());
  EXPECT_EQ(s.latest->frame_id, 129);
  EXPECT_EQ(s.latest->device_id, 1);
}

TEST(DeviceHub, FrameIdGapsAndServiceDropsCountAsDropped) {
  DeviceHub hub(four_slots());
  hub.on_device_event(appeared("A"));
  hub.on_frame(frame("A", 10, 1));
  hub.on_frame(frame("A", 11, 2));
  hub.on_frame(frame("A", 15, 3));  // 12, 13, 14 never arrived
  DeviceEvent drop;
  drop.kind = DeviceEventKind::kDroppedFrames;
  drop.info.serial = "A";
  drop.count = 2;
  hub.on_device_event(drop);
  EXPECT_EQ(hub.snapshot().devices[0].frames_dropped, 5);
}

TEST(DeviceHub, RecorderRefusalsAreCountedPerDevice) {
  DeviceHub hub(four_slots());
  CollectingConsumer c;
  c.accept = false;
  hub.set_consumer(&c);
  hub.on_frame(frame("A", 1, 1));
  hub.on_frame(frame("A", 2, 2));
  EXPECT_EQ(hub.snapshot().devices[0].frames_dropped_recorder, 2);
}

TEST(DeviceHub, LostDeviceIsMarkedAndTheOperatorTold) {
  DeviceHub hub(four_slots());
  CollectingConsumer c;
  hub.set_consumer(&c);
  hub.on_device_event(appeared("A"));
  hub.on_device_event(appeared("B"));
  hub.take_messages();
  DeviceEvent lost;
  lost.kind = DeviceEventKind::kLost;
  lost.info.serial = "B";
  hub.on_device_event(lost);
  auto snap = hub.snapshot();
  EXPECT_FALSE(snap.devices[1].connected);
  EXPECT_EQ(snap.devices[1].disconnects, 1);
  auto msgs = hub.take_messages();
  ASSERT_EQ(msgs.size(), 1u);
  EXPECT_EQ(msgs[0], "LMC2 (B) disconnected");
  hub.on_device_event(appeared("B"));
  EXPECT_TRUE(hub.snapshot().devices[1].connected);
  EXPECT_EQ(hub.snapshot().devices[1].slot, "LMC2") << "a re-plug keeps its slot (keyed by serial)";
  msgs = hub.take_messages();
  ASSERT_EQ(msgs.size(), 1u);
  EXPECT_EQ(msgs[0], "LMC2 (B) reconnected");
  ASSERT_EQ(c.events.size(), 4u);
  EXPECT_EQ(c.events[2], (std::pair<int, DeviceEventKind>{2, DeviceEventKind::kLost}));
}

TEST(DeviceHub, TrackingModeModelAndOtherSideHandsAreKeptPerDevice) {
  DeviceHub hub(four_slots());
  CollectingConsumer c;
  hub.set_consumer(&c);
  DeviceEvent a = appeared("A");
  a.info.model = "Leap Motion Controller 2";
  hub.on_device_event(a);
  hub.take_messages();
  DeviceEvent mode;
  mode.kind = DeviceEventKind::kTrackingMode;
  mode.info.serial = "A";
  mode.info.tracking_mode = "head-mounted";
  mode.message = "not the desktop mode its place in the layout needs";
  hub.on_device_event(mode);
  SourceFrame f = frame("A", 1, 1'000'000);
  f.other_side_hand = true;
  hub.on_frame(f);
  hub.on_frame(frame("A", 2, 2'000'000));
  const auto snap = hub.snapshot();
  EXPECT_EQ(snap.devices[0].model, "Leap Motion Controller 2");
  EXPECT_EQ(snap.devices[0].tracking_mode, "head-mounted");
  EXPECT_EQ(snap.devices[0].frames_other_side_hand, 1);
  EXPECT_FALSE(snap.devices[0].device_clock_us.has_value()) << "no source with a clock";
  EXPECT_EQ(hub.take_messages(),
            (std::vector<std::string>{"LMC1 (A) tracks in head-mounted mode: not the desktop mode its place in the "
                                      "layout needs"}));
  EXPECT_EQ(c.frames.size(), 2u);
  EXPECT_EQ(c.events.back(), (std::pair<int, DeviceEventKind>{1, DeviceEventKind::kTrackingMode}));
}

// The slot check against the model a device reports (core/layout/sensor_catalogue.h): an LMC2 in a
// slot laid out as the study's original controller is warned about, once; the right one is not.
TEST(DeviceHub, AControllerOfAnotherModelThanItsSlotIsWarnedAbout) {
  Layout l = four_slots();
  DeviceHub hub(l);
  DeviceEvent lmc = appeared("A1");
  lmc.info.product_id = 0x0003;
  DeviceEvent lmc2 = appeared("B2");
  lmc2.info.product_id = 0x1206;
  hub.on_device_event(lmc);
  hub.on_device_event(lmc2);
  hub.on_device_event(lmc2);  // a re-announcement does not repeat the warning
  int warnings = 0;
  for (const auto& m : hub.take_messages()) {
    if (m.rfind("warning: LMC2 is laid out as a Leap Motion Controller, as the study modelled it", 0) == 0) ++warnings;
  }
  EXPECT_EQ(warnings, 1);
  const auto snap = hub.snapshot();
  EXPECT_EQ(snap.devices[0].model_warning, "");
  EXPECT_NE(snap.devices[1].model_warning.find("Leap Motion Controller 2 (lmc2)"), std::string::npos);
  // Assigned to a slot of its own model, the warning goes.
  l.devices[3].model = "lmc2";
  DeviceHub hub2(l);
  DeviceEvent again = appeared("B2");
  again.info.product_id = 0x1206;
  hub2.on_device_event(appeared("X0"));
  hub2.on_device_event(again);
  EXPECT_NE(hub2.snapshot().devices[1].model_warning, "");
  EXPECT_EQ(hub2.assign("B2", "LMC4"), "");
  EXPECT_EQ(hub2.snapshot().devices[1].model_warning, "");
}

}  // namespace
}  // namespace lmc::devices
