// The simulated rig as a live source: it reports each controller's model and the tracking mode
// its pose implies, and its device clock can be read at any host instant, as LeapGetNow can.
#include <chrono>
#include <memory>
#include <thread>

#include <gtest/gtest.h>

#include "devices/device_hub.h"
#include "devices/sim/sim_source.h"
#include "devices/tracking_mode.h"
#include "tests/devices/sim/sim_fixtures.h"

namespace lmc::devices {
namespace sim_source_clock_test {

using sim_fixtures::paper_initial;

TEST(TrackingMode, AControllerLookingDownIsScreenTopEveryOtherDesktop) {
  Layout l = paper_initial();
  l.devices[1].pose.rx_deg = 180;  // upside down above the hand
  l.devices[1].serial = "LP2";
  l.devices[2].pose.rx_deg = 60;  // tilted, still looking up
  l.devices[2].serial = "LP3";
  EXPECT_EQ(tracking_mode_for_pose(l.devices[0].pose), TrackingMode::kDesktop);
  EXPECT_EQ(tracking_mode_for_serial(l, "LP2"), TrackingMode::kScreenTop);
  EXPECT_EQ(tracking_mode_for_serial(l, "LP3"), TrackingMode::kDesktop);
  EXPECT_EQ(tracking_mode_for_serial(l, "not in the layout"), TrackingMode::kDesktop);
  EXPECT_STREQ(tracking_mode_name(TrackingMode::kScreenTop), "screen-top");
  EXPECT_STREQ(tracking_mode_name(TrackingMode::kHeadMounted), "head-mounted");
}

TEST(SimSource, ReportsModelModeAndItsDeviceClock) {
  Layout l = paper_initial();
  l.devices[3].pose.rx_deg = 180;
  DeviceHub hub(l);
  auto source = std::make_unique<SimSource>(l, SimConfig{}, SimSourceOptions{1.0, 0.0});
  const SimSource* sim = source.get();
  EXPECT_FALSE(sim->device_clock_us(0).has_value()) << "no clock before it starts";
  hub.add_source(std::move(source));
  hub.start();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  auto every_device_streams = [&] {
    const HubSnapshot s = hub.snapshot();
    if (s.devices.size() != 4) return false;
    for (const auto& d : s.devices)
      if (d.frames_received < 3) return false;
    return true;
  };
  while (!every_device_streams() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const HubSnapshot snap = hub.snapshot();
  hub.stop();
  ASSERT_EQ(snap.devices.size(), 4u);
  for (const auto& d : snap.devices) {
    EXPECT_EQ(d.model, "simulated Leap Motion Controller") << d.slot;
    EXPECT_EQ(d.tracking_mode, d.slot == "LMC4" ? "screen-top" : "desktop") << d.slot;
    ASSERT_TRUE(d.device_clock_us.has_value()) << d.slot;
    ASSERT_TRUE(d.latest.has_value()) << d.slot;
    // The simulated frames arrive when their time comes, with no capture-to-delivery latency: the
    // clock read at the snapshot is the latest timestamp plus the time since it arrived, give or
    // take the thread's lateness in delivering it.
    const double extrapolated_us = static_cast<double>(d.latest->timestamp_us) +
                                   static_cast<double>(snap.host_time_ns - d.latest_host_receive_ns) / 1000.0;
    EXPECT_GE(*d.device_clock_us, d.latest->timestamp_us) << d.slot;
    EXPECT_NEAR(static_cast<double>(*d.device_clock_us), extrapolated_us, 100'000.0) << d.slot;
  }
}

}  // namespace sim_source_clock_test
}  // namespace lmc::devices
