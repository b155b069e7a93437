// The allowed Vicon senders (devices/vicon/vicon_senders.h) and where a listener binds
// (vicon_route.h): parsing, matching and the messages for bad entries. Names are resolved by a
// fake resolver, so no test depends on the network's DNS.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "devices/vicon/vicon_route.h"
#include "devices/vicon/vicon_senders.h"

namespace lmc::devices {
namespace vicon_senders_test {  // named: test files share unity batches

std::uint32_t ip(const char* text) {
  return *parse_ipv4(text);
}

std::vector<std::uint32_t> fake_dns(const std::string& name) {
  if (name == "vicon-pc.lab") return {ip("10.0.0.7"), ip("10.0.0.8")};
  throw Error("Vicon host '" + name + "' cannot be resolved: unknown");
}

std::string error_of(const std::string& list) {
  try {
    ViconSenders::parse(list, fake_dns);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ViconSenders, ParsesDottedQuadsStrictly) {
  EXPECT_EQ(parse_ipv4("10.0.0.5"), 0x0A000005u);
  EXPECT_EQ(parse_ipv4("255.255.255.255"), 0xFFFFFFFFu);
  EXPECT_EQ(parse_ipv4("0.0.0.0"), 0u);
  for (const char* bad : {"10.0.0", "10.0.0.5.1", "10.0.0.256", "10.0.0.", "a.b.c.d", "10.0.0.05", " 10.0.0.5", ""})
    EXPECT_FALSE(parse_ipv4(bad).has_value()) << bad;
  EXPECT_EQ(format_ipv4(0x7F000002u), "127.0.0.2");
}

TEST(ViconSenders, EmptyListAllowsAnySender) {
  const ViconSenders s = ViconSenders::parse("  ", fake_dns);
  EXPECT_TRUE(s.any());
  EXPECT_TRUE(s.allows(ip("192.168.1.1")));
  EXPECT_EQ(s.describe(), "any sender");
}

TEST(ViconSenders, OneAddressAllowsThatHostOnly) {
  const ViconSenders s = ViconSenders::parse("127.0.0.1", fake_dns);
  EXPECT_FALSE(s.any());
  EXPECT_TRUE(s.allows(ip("127.0.0.1")));
  EXPECT_FALSE(s.allows(ip("127.0.0.2")));
  EXPECT_EQ(s.describe(), "127.0.0.1");
}

TEST(ViconSenders, SubnetsNamesAndListsCombine) {
  const ViconSenders s = ViconSenders::parse(" 10.0.1.0/24 , vicon-pc.lab,192.168.5.9/32", fake_dns);
  ASSERT_EQ(s.rules().size(), 4u);  // the name gave two addresses
  EXPECT_EQ(s.rules()[0].prefix, 24);
  EXPECT_EQ(s.rules()[0].network, ip("10.0.1.0"));
  EXPECT_TRUE(s.allows(ip("10.0.1.0")));
  EXPECT_TRUE(s.allows(ip("10.0.1.255")));
  EXPECT_FALSE(s.allows(ip("10.0.2.1")));
  EXPECT_TRUE(s.allows(ip("10.0.0.7")));
  EXPECT_TRUE(s.allows(ip("10.0.0.8")));
  EXPECT_FALSE(s.allows(ip("10.0.0.9")));
  EXPECT_TRUE(s.allows(ip("192.168.5.9")));
  EXPECT_FALSE(s.allows(ip("192.168.5.10")));
  EXPECT_EQ(s.describe(), "10.0.1.0/24, vicon-pc.lab (10.0.0.7, 10.0.0.8), 192.168.5.9/32");
}

TEST(ViconSenders, HostBitsOfASubnetAreMaskedAndSlashZeroAllowsEveryone) {
  const ViconSenders s = ViconSenders::parse("10.0.0.5/16", fake_dns);
  EXPECT_EQ(s.rules()[0].network, ip("10.0.0.0"));
  EXPECT_TRUE(s.allows(ip("10.0.200.3")));
  EXPECT_FALSE(s.allows(ip("10.1.0.1")));
  const ViconSenders all = ViconSenders::parse("0.0.0.0/0", fake_dns);
  EXPECT_FALSE(all.any());  // said on purpose: no warning is due
  EXPECT_TRUE(all.allows(ip("203.0.113.4")));
}

TEST(ViconSenders, BadEntriesAreNamedInTheMessage) {
  EXPECT_NE(error_of("10.0.0.300").find("'10.0.0.300' is not an IPv4 address"), std::string::npos)
      << error_of("10.0.0.300");
  EXPECT_NE(error_of("10.0.0.5,,10.0.0.6").find("an entry is empty"), std::string::npos);
  EXPECT_NE(error_of("10.0.0.0/33").find("'10.0.0.0/33': the prefix length must be 0 to 32"), std::string::npos);
  EXPECT_NE(error_of("10.0.0.0/x").find("prefix length"), std::string::npos);
  EXPECT_NE(error_of("fe80::1").find("IPv6 is not supported"), std::string::npos);
  EXPECT_NE(error_of("10.0.0.5:30").find("the port is the listen port"), std::string::npos);
  EXPECT_NE(error_of("vicon_pc!").find("'vicon_pc!' is not an IPv4 address or host name"), std::string::npos);
  EXPECT_NE(error_of("nowhere.lab").find("Vicon host 'nowhere.lab' cannot be resolved"), std::string::npos);
  EXPECT_NE(error_of("10.0.0.5, 10.0.0.300").find("Vicon host list '10.0.0.5, 10.0.0.300'"), std::string::npos);
}

TEST(ViconListenBinding, AnExplicitAddressIsKeptAndNoHostsMeansEveryInterface) {
  const ViconSenders lo = ViconSenders::parse("127.0.0.1", fake_dns);
  EXPECT_EQ(choose_vicon_listen_binding("127.0.0.1", lo).address, "127.0.0.1");
  EXPECT_TRUE(choose_vicon_listen_binding("127.0.0.1", lo).interface_name.empty());
  const ViconListenBinding any = choose_vicon_listen_binding("", ViconSenders());
  EXPECT_EQ(any.address, "0.0.0.0");
  EXPECT_TRUE(any.interface_name.empty());
}

TEST(ViconListenBinding, ALoopbackHostIsReachedThroughTheLoopbackInterface) {
  const auto local = local_address_towards(ip("127.0.0.1"));
  ASSERT_TRUE(local.has_value());
  EXPECT_EQ(*local, ip("127.0.0.1"));
  const std::string lo = interface_with_address(ip("127.0.0.1"));
  ASSERT_FALSE(lo.empty());
  const ViconListenBinding b = choose_vicon_listen_binding("", ViconSenders::parse("127.0.0.1", fake_dns));
  EXPECT_EQ(b.address, "0.0.0.0");  // not 127.0.0.1: broadcasts to the interface must still arrive
  EXPECT_EQ(b.interface_name, lo);
  EXPECT_EQ(b.local_address, "127.0.0.1");
  EXPECT_NE(b.note.find("the interface that reaches 127.0.0.1"), std::string::npos) << b.note;
}

}  // namespace vicon_senders_test
}  // namespace lmc::devices
