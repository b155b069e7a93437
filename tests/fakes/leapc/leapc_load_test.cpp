// The LeapC backend's poll thread under a bench's full load: eight controllers at 120 Hz, their
// tracking events interleaved by the service in a different order every tick, delivered in real
// time for three seconds. Nothing may be dropped between the service and the hub, and every frame
// must reach the slot of its controller's serial, whatever id the service gave the controller.
#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <random>
#include <thread>

#include <gtest/gtest.h>

#include "devices/device_hub.h"
#include "devices/leapc/leapc_source.h"
#include "fake_leapc.h"
#include "leapc_test_support.h"

namespace lmc::devices {
namespace {

TEST(LeapcLoad, EightControllersAt120HzInterleavedLoseNothingAndKeepTheirSlots) {
  fake_leapc::reset();
  constexpr int kDevices = 8;
  constexpr int kTicks = 360;  // 3 s at 120 Hz
  constexpr auto kPeriod = std::chrono::microseconds(8'333);

  DeviceHub hub(layout_with_serials(kDevices));
  Recorded rec;
  hub.set_consumer(&rec);
  hub.add_source(std::make_unique<LeapcSource>(test_options()));
  hub.start();
  // The service's ids are not the slot order: slot s (1-based) gets id 40 + (s * 5) % 8.
  std::array<std::uint32_t, kDevices> id_of_slot{};
  for (int s = 1; s <= kDevices; ++s) {
    id_of_slot[s - 1] = 40u + static_cast<std::uint32_t>((s * 5) % kDevices);
    fake_leapc::plug(id_of_slot[s - 1], "LP" + std::string(5, static_cast<char>('0' + s)));
  }
  ASSERT_TRUE(wait_for([&] { return hub.serial_to_slot().size() == kDevices; }));

  // Each slot's hand is placed at 100 × slot mm, so a frame says by itself whose it is.
  std::array<leapc::Hand, kDevices> hand_of_slot{};
  for (int s = 1; s <= kDevices; ++s) hand_of_slot[s - 1] = fake_leapc::make_hand(leapc::kHandRight, 100.0F * s);
  std::mt19937 shuffle_rng(7);
  std::array<int, kDevices> order{};
  for (int i = 0; i < kDevices; ++i) order[i] = i;
  auto next = std::chrono::steady_clock::now();
  for (int tick = 0; tick < kTicks; ++tick) {
    std::shuffle(order.begin(), order.end(), shuffle_rng);
    for (const int i : order)
      fake_leapc::track(id_of_slot[i], 1000 + tick, 5'000'000 + tick * 8'333 + i * 97, 120.0F, {hand_of_slot[i]});
    next += kPeriod;
    std::this_thread::sleep_until(next);
  }
  ASSERT_TRUE(wait_for([&] { return rec.size() == kDevices * kTicks; }, 10'000))
      << rec.size() << " of " << kDevices * kTicks << " frames reached the hub";
  const HubSnapshot snap = hub.snapshot();
  hub.stop();

  const auto st = fake_leapc::stats();
  EXPECT_EQ(st.tracking_delivered, kDevices * kTicks);
  EXPECT_EQ(st.tracking_suppressed, 0);
  EXPECT_EQ(st.concurrent_polls, 0);
  // Per slot: every frame, in order, with its own hand.
  std::map<int, std::vector<std::int64_t>> frame_ids_by_slot;
  for (const auto& f : rec.frames) {
    ASSERT_TRUE(f.hand_present);
    ASSERT_GE(f.device_id, 1);
    ASSERT_LE(f.device_id, kDevices);
    EXPECT_DOUBLE_EQ(f.point(kPalm).x(), 100.0 * f.device_id) << "a frame of LMC" << f.device_id;
    frame_ids_by_slot[f.device_id].push_back(f.frame_id);
  }
  ASSERT_EQ(frame_ids_by_slot.size(), static_cast<size_t>(kDevices));
  for (const auto& [slot, ids] : frame_ids_by_slot) {
    ASSERT_EQ(ids.size(), static_cast<size_t>(kTicks)) << "LMC" << slot;
    for (int k = 0; k < kTicks; ++k) ASSERT_EQ(ids[k], 1000 + k) << "LMC" << slot << " frame " << k;
  }
  ASSERT_EQ(snap.devices.size(), static_cast<size_t>(kDevices));
  for (const auto& d : snap.devices) {
    EXPECT_TRUE(d.connected) << d.slot;
    EXPECT_EQ(d.frames_received, kTicks) << d.slot;
    EXPECT_EQ(d.frames_dropped, 0) << d.slot;
    EXPECT_EQ(d.frames_dropped_recorder, 0) << d.slot;
  }
  fake_leapc::reset();
}

}  // namespace
}  // namespace lmc::devices
