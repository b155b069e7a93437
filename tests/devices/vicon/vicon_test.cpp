// Vicon UDP trigger: message format and, over real sockets on loopback only, the sender and
// listener (docs/algorithms/vicon.md). 127.0.0.2 stands for another machine on
// the lab network: Linux delivers all of 127.0.0.0/8 on the loopback interface.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "devices/vicon/vicon_message.h"
#include "devices/vicon/vicon_route.h"
#include "devices/vicon/vicon_senders.h"
#include "devices/vicon/vicon_trigger.h"
#include "tests/devices/vicon/vicon_send_from.h"
#include "tests/support/reference_data.h"

namespace lmc::devices {
namespace {

using test::vicon_send_from;

TEST(ViconMessage, StartHasEveryFieldAndIsNullTerminated) {
  ViconMessage m;
  m.name = "Naiv_Static101";
  m.notes = "subject 1";
  m.description = "static";
  m.database_path = "D:/data";
  m.delay_ms = 40;
  m.packet_id = 7;
  const std::string p = format_vicon_message(m);
  ASSERT_FALSE(p.empty());
  EXPECT_EQ(p.back(), '\0');
  EXPECT_EQ(p.find('\0'), p.size() - 1);
  EXPECT_NE(p.find("<CaptureStart><Name VALUE=\"Naiv_Static101\"/><Notes VALUE=\"subject 1\"/>"), std::string::npos);
  EXPECT_NE(p.find("<Delay VALUE=\"40\"/><PacketID VALUE=\"7\"/></CaptureStart>"), std::string::npos);
  auto back = parse_vicon_message(p);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, m);
}

TEST(ViconMessage, StopCarriesResultAndRoundTrips) {
  ViconMessage m;
  m.type = ViconMessage::Type::kStop;
  m.name = "t1";
  m.packet_id = 4000000000u;
  m.result = "CANCEL";
  const std::string p = format_vicon_message(m);
  EXPECT_NE(p.find("<CaptureStop RESULT=\"CANCEL\">"), std::string::npos);
  EXPECT_EQ(p.find("Notes"), std::string::npos);
  auto back = parse_vicon_message(p);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, m);
}

TEST(ViconMessage, ValuesAreXmlEscaped) {
  ViconMessage m;
  m.name = "a\"b";
  m.notes = "<x> & 'y'";
  m.description = std::string("ctl\x01") + '\0' + "z";
  const std::string p = format_vicon_message(m);
  EXPECT_NE(p.find("Name VALUE=\"a&quot;b\""), std::string::npos);
  EXPECT_NE(p.find("Notes VALUE=\"&lt;x&gt; &amp; &apos;y&apos;\""), std::string::npos);
  EXPECT_EQ(p.find('\0'), p.size() - 1);  // an embedded NUL would cut the datagram
  auto back = parse_vicon_message(p);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->notes, "<x> & 'y'");
  EXPECT_EQ(back->description, "ctlz");
}

// The escaping is core's (core/common/xml_text.h) with the Vicon rule for breaks: a tab is kept and
// line breaks are dropped, so the bytes sent for valid text are what Vicon always received; what is
// not UTF-8 becomes U+FFFD, so the receiver's XML parser never sees an invalid document.
TEST(ViconMessage, TabsStayLineBreaksGoAndInvalidUtf8IsReplaced) {
  ViconMessage m;
  m.notes = "a\tb\nc\rd \xC2\xB0 \x7F";
  m.description = "bad \xFF byte";
  const std::string p = format_vicon_message(m);
  EXPECT_NE(p.find("<Notes VALUE=\"a\tbcd \xC2\xB0 \x7F\"/>"), std::string::npos) << p;
  EXPECT_NE(p.find("<Description VALUE=\"bad \xEF\xBF\xBD byte\"/>"), std::string::npos) << p;
  const auto back = parse_vicon_message(p);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->notes, "a\tbcd \xC2\xB0 \x7F");
}

TEST(ViconMessage, RejectsOtherDocuments) {
  std::string why;
  EXPECT_FALSE(parse_vicon_message("<Hello/>", &why).has_value());
  EXPECT_NE(why.find("not a CaptureStart"), std::string::npos);
  EXPECT_FALSE(parse_vicon_message("<CaptureStart><Name VALUE=\"x\"/>", &why).has_value());
  EXPECT_FALSE(parse_vicon_message("<CaptureStart><Name VALUE=\"x\"/><PacketID VALUE=\"q\"/></CaptureStart>", &why));
  EXPECT_NE(why.find("PacketID"), std::string::npos);
}

TEST(ViconTarget, ParsesHostAndPort) {
  auto c = parse_vicon_target("127.0.0.1:9030");
  EXPECT_EQ(c.host, "127.0.0.1");
  EXPECT_EQ(c.port, 9030);
  EXPECT_EQ(parse_vicon_target("127.0.0.1").port, 30);
  EXPECT_THROW(parse_vicon_target("127.0.0.1:0"), Error);
  EXPECT_THROW(parse_vicon_target("127.0.0.1:70000"), Error);
  EXPECT_THROW(parse_vicon_target("127.0.0.1:x"), Error);
  EXPECT_THROW(parse_vicon_target(":30"), Error);
}

TEST(ViconTrigger, MalformedNumericHostIsReportedWithoutALookup) {
  ViconTriggerConfig c;
  c.host = "300.1.1.1";
  try {
    ViconTrigger t(c);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("300.1.1.1"), std::string::npos);
  }
}

TEST(ViconTrigger, LoopbackListenerReceivesStartAndStopEachRepeatedThreeTimes) {
  std::mutex m;
  std::vector<ViconMessage> got;
  ViconListener listener("127.0.0.1", 0, [&](const ViconMessage& msg) {
    std::lock_guard lock(m);
    got.push_back(msg);
  });
  ASSERT_NE(listener.port(), 0);
  ViconTriggerConfig c;
  c.host = "127.0.0.1";
  c.port = listener.port();
  c.first_packet_id = 500;
  c.database_path = "C:/Vicon/Session 1";
  ViconTrigger trigger(c);
  const auto start = trigger.send_start("Naiv_Index103");
  ASSERT_TRUE(start.ok()) << start.error;
  EXPECT_EQ(start.datagrams_sent, 3);
  EXPECT_EQ(start.message.packet_id, 500u);
  const auto stop = trigger.send_stop("Naiv_Index103");
  ASSERT_TRUE(stop.ok()) << stop.error;
  EXPECT_EQ(stop.message.packet_id, 501u);

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (listener.datagrams_received() < 6 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(listener.datagrams_received(), 6);
  EXPECT_EQ(listener.rejected(), 0);
  std::lock_guard lock(m);
  ASSERT_EQ(got.size(), 2u);  // repeats share a PacketID and are dropped by the receiver
  EXPECT_EQ(got[0].type, ViconMessage::Type::kStart);
  EXPECT_EQ(got[0].name, "Naiv_Index103");
  EXPECT_EQ(got[0].database_path, "C:/Vicon/Session 1");
  EXPECT_EQ(got[0].packet_id, 500u);
  EXPECT_EQ(got[1].type, ViconMessage::Type::kStop);
  EXPECT_EQ(got[1].result, "SUCCESS");
  EXPECT_EQ(got[1].packet_id, 501u);
}

TEST(ViconTrigger, UnreachablePortIsReportedNotIgnored) {
  // A loopback port nobody listens on: the kernel answers with "port unreachable", which a
  // connected UDP socket reports on a following send.
  const int probe = ::socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(probe, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(probe, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  socklen_t len = sizeof addr;
  ::getsockname(probe, reinterpret_cast<sockaddr*>(&addr), &len);
  const std::uint16_t port = ntohs(addr.sin_port);
  ::close(probe);

  ViconTriggerConfig c;
  c.host = "127.0.0.1";
  c.port = port;
  c.repeats = 3;
  c.repeat_interval_ms = 20;
  c.packet_id_file = test::scratch_dir("vicon_unreachable") / "vicon-packet-id";  // not the user's state
  ViconTrigger trigger(c);
  std::string error;
  for (int i = 0; i < 5 && error.empty(); ++i) error = trigger.send_start("t").error;
  EXPECT_NE(error.find("refused"), std::string::npos) << error;
  EXPECT_NE(error.find("127.0.0.1:" + std::to_string(port)), std::string::npos) << error;
}

// A UDP socket on a free loopback port that swallows whatever arrives (no ICMP errors).
struct Sink {
  int fd = -1;
  std::uint16_t port = 0;
  Sink() {
    fd = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
    socklen_t len = sizeof addr;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
    port = ntohs(addr.sin_port);
  }
  ~Sink() { ::close(fd); }
};

TEST(ViconTrigger, PacketIdsNeverRepeatForSessionsStartedInTheSameSecond) {
  Sink sink;
  const auto file = test::scratch_dir("vicon_ids") / "state" / "vicon-packet-id";
  ViconTriggerConfig c;
  c.host = "127.0.0.1";
  c.port = sink.port;
  c.repeats = 1;
  c.packet_id_file = file;
  std::vector<std::uint32_t> ids;
  // Three sessions back to back (well within one second), each with a start and a stop; the
  // second and third even exist while the first is still open, as two programs would.
  ViconTrigger a(c);
  ViconTrigger b(c);
  for (ViconTrigger* t : {&a, &b}) {
    const auto start = t->send_start("t");
    const auto stop = t->send_stop("t");
    ASSERT_TRUE(start.ok() && stop.ok()) << start.error << stop.error;
    EXPECT_TRUE(start.warning.empty()) << start.warning;
    ids.push_back(start.message.packet_id);
    ids.push_back(stop.message.packet_id);
  }
  {
    ViconTrigger later(c);
    ids.push_back(later.send_start("t").message.packet_id);
    ids.push_back(later.send_stop("t").message.packet_id);
  }
  // Strictly increasing, so never repeated (a trigger made in the next second starts from the
  // clock base, 10 further on; within one second each ID is the last + 1).
  for (size_t i = 1; i < ids.size(); ++i) EXPECT_GT(ids[i], ids[i - 1]) << "IDs keep incrementing: " << i;
  for (size_t i = 1; i < ids.size(); i += 2) EXPECT_EQ(ids[i], ids[i - 1] + 1) << "stop follows its start: " << i;
  // The base comes from the clock (seconds × 10): a fresh state file starts there.
  const auto secs =
      std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  const auto clock_id = static_cast<std::uint32_t>((secs * 10) & 0x7FFFFFFF);
  EXPECT_LE(ids.front(), clock_id);
  EXPECT_GE(ids.front() + 20, clock_id);
  // The state file holds the last ID used.
  std::ifstream in(file);
  std::uint32_t last = 0;
  in >> last;
  EXPECT_EQ(last, ids.back());
}

TEST(ViconTrigger, AnUnusablePacketIdFileIsReportedAndSendingGoesOn) {
  Sink sink;
  const auto dir = test::scratch_dir("vicon_ids_bad");
  ViconTriggerConfig c;
  c.host = "127.0.0.1";
  c.port = sink.port;
  c.repeats = 1;
  c.packet_id_file = dir;  // a folder, not a file
  ViconTrigger t(c);
  const auto r = t.send_start("t");
  EXPECT_TRUE(r.ok()) << r.error;
  EXPECT_NE(r.warning.find("PacketID file"), std::string::npos) << r.warning;
  EXPECT_EQ(t.send_stop("t").message.packet_id, r.message.packet_id + 1);
}

TEST(ViconTrigger, GivenFirstPacketIdIsUsedAsIsAndNothingIsPersisted) {
  Sink sink;
  const auto file = test::scratch_dir("vicon_ids_given") / "vicon-packet-id";
  ViconTriggerConfig c;
  c.host = "127.0.0.1";
  c.port = sink.port;
  c.repeats = 1;
  c.first_packet_id = 42;
  c.packet_id_file = file;
  ViconTrigger t(c);
  EXPECT_EQ(t.send_start("t").message.packet_id, 42u);
  EXPECT_EQ(t.send_stop("t").message.packet_id, 43u);
  EXPECT_FALSE(std::filesystem::exists(file));
}

ViconMessage vicon_capture(ViconMessage::Type type, const std::string& name, std::uint32_t packet_id) {
  ViconMessage m;
  m.type = type;
  m.name = name;
  m.packet_id = packet_id;
  return m;
}

TEST(ViconListener, OnlyTheConfiguredHostIsObeyedAndEveryOtherDatagramIsCountedWithItsSender) {
  std::mutex m;
  std::vector<std::pair<ViconMessage, ViconSender>> got;
  ViconListenerConfig config;
  config.bind_address = "127.0.0.1";
  config.port = 0;
  config.allowed = ViconSenders::parse("127.0.0.1");
  ViconListener listener(config, [&](const ViconMessage& msg, const ViconSender& from) {
    std::lock_guard lock(m);
    got.emplace_back(msg, from);
  });
  ASSERT_NE(listener.port(), 0);
  // The other host speaks first, with the PacketIDs the lab's Vicon is about to use: a refused
  // datagram must neither start anything nor make the real message look like a repeat.
  vicon_send_from("127.0.0.2", listener.port(), vicon_capture(ViconMessage::Type::kStart, "Intruder", 800), 3);
  ViconTriggerConfig c;
  c.host = "127.0.0.1";
  c.port = listener.port();
  c.first_packet_id = 800;
  ViconTrigger vicon(c);
  ASSERT_TRUE(vicon.send_start("Naiv_Index103").ok());
  ASSERT_TRUE(vicon.send_stop("Naiv_Index103").ok());
  vicon_send_from("127.0.0.2", listener.port(), vicon_capture(ViconMessage::Type::kStop, "Naiv_Index103", 802), 3);

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (listener.datagrams_received() < 12 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(listener.datagrams_received(), 12);
  EXPECT_EQ(listener.refused(), 6);
  EXPECT_EQ(listener.rejected(), 0);
  {
    std::lock_guard lock(m);
    ASSERT_EQ(got.size(), 2u);
    EXPECT_EQ(got[0].first.type, ViconMessage::Type::kStart);
    EXPECT_EQ(got[0].first.name, "Naiv_Index103");
    EXPECT_EQ(got[0].first.packet_id, 800u);
    EXPECT_EQ(got[0].second.host(), "127.0.0.1");
    EXPECT_EQ(got[1].first.type, ViconMessage::Type::kStop);
    EXPECT_EQ(got[1].first.packet_id, 801u);
    EXPECT_EQ(got[1].second.host(), "127.0.0.1");
  }
  const auto by_host = listener.refused_by_host();
  ASSERT_EQ(by_host.size(), 1u);
  EXPECT_EQ(by_host[0].first, "127.0.0.2");
  EXPECT_EQ(by_host[0].second, 6);
  // The repeats of one message from one sender are one refusal to report.
  std::int64_t not_listed = -1;
  const std::vector<ViconRefusal> refusals = listener.take_refusals(&not_listed);
  EXPECT_EQ(not_listed, 0);
  ASSERT_EQ(refusals.size(), 2u);
  EXPECT_EQ(refusals[0].sender.host(), "127.0.0.2");
  EXPECT_EQ(refusals[0].what, "CaptureStart 'Intruder' (PacketID 800)");
  EXPECT_EQ(refusals[0].datagrams, 3);
  EXPECT_EQ(refusals[1].what, "CaptureStop 'Naiv_Index103' (PacketID 802)");
  EXPECT_EQ(refusals[1].datagrams, 3);
  EXPECT_TRUE(listener.take_refusals().empty());
}

TEST(ViconListener, TiedToTheInterfaceThatReachesTheHostItStillHearsIt) {
  const ViconSenders allowed = ViconSenders::parse("127.0.0.1");
  const ViconListenBinding binding = choose_vicon_listen_binding("", allowed);
  ASSERT_FALSE(binding.interface_name.empty());
  std::atomic<int> obeyed{0};
  ViconListenerConfig config;
  config.bind_address = binding.address;
  config.interface_name = binding.interface_name;
  config.port = 0;
  config.allowed = allowed;
  ViconListener listener(config, [&](const ViconMessage&, const ViconSender&) { ++obeyed; });
  vicon_send_from("127.0.0.1", listener.port(), vicon_capture(ViconMessage::Type::kStart, "t", 5), 1);
  vicon_send_from("127.0.0.2", listener.port(), vicon_capture(ViconMessage::Type::kStart, "t", 6), 2);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (listener.datagrams_received() < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(obeyed.load(), 1);
  EXPECT_EQ(listener.refused(), 2);
}

}  // namespace
}  // namespace lmc::devices
