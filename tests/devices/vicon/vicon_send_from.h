#pragma once
// A Vicon trigger message sent from another host, as the devices tests need it: the trigger and
// the trial engine both refuse a sender that is not the configured Vicon host. POSIX sockets (the
// Windows build leaves these test files out: tests/CMakeLists.txt, LMC_POSIX_ONLY_TESTS).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "devices/vicon/vicon_message.h"

namespace lmc::test {

// Sends `message` `times` times from a UDP socket bound to `from` (127.0.0.2: another machine on
// the lab network) to 127.0.0.1:port.
inline void vicon_send_from(const char* from, std::uint16_t port, const devices::ViconMessage& message, int times) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_in local{};
  local.sin_family = AF_INET;
  ASSERT_EQ(inet_pton(AF_INET, from, &local.sin_addr), 1);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&local), sizeof local), 0) << from;
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(port);
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const std::string payload = devices::format_vicon_message(message);
  for (int i = 0; i < times; ++i)
    EXPECT_EQ(::sendto(fd, payload.data(), payload.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to),
              static_cast<ssize_t>(payload.size()));
  ::close(fd);
}

}  // namespace lmc::test
