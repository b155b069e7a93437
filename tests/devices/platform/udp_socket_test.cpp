// The socket and timer seams (devices/platform) on both systems: Winsock's start-up, its address
// reuse rules, the Vicon trigger over loopback, and 120 Hz pacing.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "core/common/error.h"
#include "devices/platform/fine_timer.h"
#include "devices/platform/udp_socket.h"
#include "devices/vicon/vicon_trigger.h"

using lmc::devices::net::UdpSocket;

namespace {
constexpr std::uint32_t kLoopback = 0x7F000001u;
}

TEST(UdpSocket, ADatagramCrossesLoopbackWithItsSender) {
  UdpSocket receiver("test receiver");
  ASSERT_TRUE(receiver.bind(kLoopback, 0)) << receiver.error();
  const std::uint16_t port = receiver.local_port();
  ASSERT_NE(port, 0);
  UdpSocket sender("test sender");
  ASSERT_TRUE(sender.connect(kLoopback, port)) << sender.error();
  ASSERT_EQ(sender.send("hello"), 5) << sender.error();
  char buf[64];
  std::uint32_t from = 0;
  std::uint16_t from_port = 0;
  const long long n = receiver.receive(buf, sizeof buf, &from, &from_port, 2000);
  ASSERT_EQ(n, 5) << receiver.error();
  EXPECT_EQ(std::string(buf, 5), "hello");
  EXPECT_EQ(from, kLoopback);
  EXPECT_EQ(from_port, sender.local_port());
  // Nothing more: a timeout is 0, not an error.
  EXPECT_EQ(receiver.receive(buf, sizeof buf, &from, &from_port, 20), 0);
}

TEST(UdpSocket, ResolvesNumbersWithoutAResolverAndRefusesTypos) {
  std::string why;
  const auto ok = lmc::devices::net::resolve_ipv4("127.0.0.1", true, &why);
  ASSERT_EQ(ok.size(), 1u) << why;
  EXPECT_EQ(ok[0], kLoopback);
  EXPECT_TRUE(lmc::devices::net::resolve_ipv4("300.1.1.1", true, &why).empty());
  EXPECT_FALSE(why.empty());
}

TEST(UdpSocket, ASecondListenerOnAClaimedPort) {
  UdpSocket first("first listener");
  first.claim_port();
  ASSERT_TRUE(first.bind(kLoopback, 0)) << first.error();
  UdpSocket second("second listener");
  second.claim_port();
  const bool bound = second.bind(kLoopback, first.local_port());
#ifdef _WIN32
  // Windows' SO_REUSEADDR would let the second take the first's datagrams; the exclusive claim
  // refuses it, and the reason reaches the listener's message.
  EXPECT_FALSE(bound);
  EXPECT_FALSE(second.error().empty());
#else
  // Linux lets two sockets that both ask for address reuse share a UDP port (a restarted listener
  // binds at once); the sender filter, not the port, keeps strangers out.
  EXPECT_TRUE(bound) << second.error();
#endif
}

TEST(UdpSocket, TheViconTriggerReachesAListenerOverLoopback) {
  std::atomic<int> got{0};
  lmc::devices::ViconListener listener(
      "127.0.0.1", 0, [&](const lmc::devices::ViconMessage& m) { got += m.name == "Trial 1" ? 1 : 0; });
  lmc::devices::ViconTriggerConfig c;
  c.host = "127.0.0.1";
  c.port = listener.port();
  c.first_packet_id = 5;
  lmc::devices::ViconTrigger trigger(c);
  const auto sent = trigger.send_start("Trial 1");
  ASSERT_TRUE(sent.error.empty()) << sent.error;
  EXPECT_EQ(sent.datagrams_sent, 3);
  for (int i = 0; i < 200 && got == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(got, 1);  // three repeats, one message
}

TEST(FineTimerResolution, PacesFramesAt120Hz) {
  // Windows' default timer wakes a sleeping thread every 15.6 ms: without the fine timer a 120 Hz
  // source would deliver frames two at a time. The median frame interval must be the frame period.
  const lmc::devices::FineTimerResolution fine;
  using Clock = std::chrono::steady_clock;
  const auto period = std::chrono::nanoseconds(1'000'000'000 / 120);
  std::vector<double> intervals_ms;
  auto due = Clock::now();
  auto last = due;
  for (int i = 0; i < 120; ++i) {
    due += period;
    while (Clock::now() < due)
      std::this_thread::sleep_for(std::min<Clock::duration>(due - Clock::now(), std::chrono::milliseconds(20)));
    const auto now = Clock::now();
    intervals_ms.push_back(std::chrono::duration<double, std::milli>(now - last).count());
    last = now;
  }
  std::sort(intervals_ms.begin(), intervals_ms.end());
  const double median = intervals_ms[intervals_ms.size() / 2];
  EXPECT_NEAR(median, 1000.0 / 120.0, 1.0);
  // With the coarse timer every other frame comes at once after a late one (about half of them);
  // a busy machine makes a few such pairs too, never a quarter.
  const auto bursts = std::count_if(intervals_ms.begin(), intervals_ms.end(), [](double v) { return v < 0.5 * 8.33; });
  EXPECT_LT(bursts, 30);
}
