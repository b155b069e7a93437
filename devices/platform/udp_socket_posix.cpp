#ifndef _WIN32
#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "core/common/error.h"
#include "core/platform/system_error.h"
#include "devices/platform/udp_socket.h"

namespace lmc::devices::net {
namespace {

sockaddr_in endpoint(std::uint32_t address, std::uint16_t port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  a.sin_addr.s_addr = htonl(address);
  return a;
}

int fd_of(std::intptr_t handle) { return static_cast<int>(handle); }

}  // namespace

UdpSocket::UdpSocket(const std::string& who) : handle_(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0)) {
  if (handle_ < 0) throw Error(who + ": cannot open a UDP socket: " + platform::last_system_error());
}

UdpSocket::~UdpSocket() {
  if (handle_ >= 0) ::close(fd_of(handle_));
}

UdpSocket::UdpSocket(UdpSocket&& other) noexcept : handle_(other.handle_), error_(std::move(other.error_)) {
  other.handle_ = -1;
}

void UdpSocket::fail() { error_ = platform::last_system_error(); }

bool UdpSocket::enable_broadcast() {
  const int on = 1;
  if (setsockopt(fd_of(handle_), SOL_SOCKET, SO_BROADCAST, &on, sizeof on) == 0) return true;
  fail();
  return false;
}

void UdpSocket::claim_port() {
  const int on = 1;
  setsockopt(fd_of(handle_), SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
}

bool UdpSocket::bind_to_interface(const std::string& name) {
  if (setsockopt(fd_of(handle_), SOL_SOCKET, SO_BINDTODEVICE, name.c_str(), static_cast<socklen_t>(name.size())) == 0)
    return true;
  fail();
  return false;
}

bool UdpSocket::bind(std::uint32_t address, std::uint16_t port) {
  const sockaddr_in a = endpoint(address, port);
  if (::bind(fd_of(handle_), reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0) return true;
  fail();
  return false;
}

bool UdpSocket::connect(std::uint32_t address, std::uint16_t port) {
  const sockaddr_in a = endpoint(address, port);
  if (::connect(fd_of(handle_), reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0) return true;
  fail();
  return false;
}

std::optional<std::uint32_t> UdpSocket::local_address() {
  sockaddr_in local{};
  socklen_t len = sizeof local;
  if (::getsockname(fd_of(handle_), reinterpret_cast<sockaddr*>(&local), &len) == 0) return ntohl(local.sin_addr.s_addr);
  fail();
  return std::nullopt;
}

std::uint16_t UdpSocket::local_port() {
  sockaddr_in local{};
  socklen_t len = sizeof local;
  if (::getsockname(fd_of(handle_), reinterpret_cast<sockaddr*>(&local), &len) != 0) return 0;
  return ntohs(local.sin_port);
}

long long UdpSocket::send(std::string_view data) {
  ssize_t n = -1;
  do {
    n = ::send(fd_of(handle_), data.data(), data.size(), 0);
  } while (n < 0 && errno == EINTR);
  if (n < 0) fail();
  return n;
}

long long UdpSocket::receive(char* buffer, std::size_t size, std::uint32_t* from_address, std::uint16_t* from_port,
                             int timeout_ms) {
  pollfd p{fd_of(handle_), POLLIN, 0};
  if (const int ready = ::poll(&p, 1, timeout_ms); ready <= 0) {
    if (ready < 0 && errno != EINTR) {
      fail();
      return -1;
    }
    return 0;
  }
  sockaddr_in from{};
  socklen_t from_len = sizeof from;
  const ssize_t n = ::recvfrom(fd_of(handle_), buffer, size, 0, reinterpret_cast<sockaddr*>(&from), &from_len);
  if (n < 0) {
    fail();
    return -1;
  }
  *from_address = ntohl(from.sin_addr.s_addr);
  *from_port = ntohs(from.sin_port);
  return n;
}

std::vector<std::uint32_t> resolve_ipv4(const std::string& name, bool numeric_only, std::string* error) {
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_DGRAM;
  if (numeric_only) hints.ai_flags = AI_NUMERICHOST;
  addrinfo* res = nullptr;
  std::vector<std::uint32_t> out;
  if (const int rc = getaddrinfo(name.c_str(), nullptr, &hints, &res); rc != 0 || res == nullptr) {
    *error = gai_strerror(rc);
    return out;
  }
  for (const addrinfo* p = res; p != nullptr; p = p->ai_next) {
    sockaddr_in addr{};
    std::memcpy(&addr, p->ai_addr, sizeof addr);
    const std::uint32_t a = ntohl(addr.sin_addr.s_addr);
    if (std::find(out.begin(), out.end(), a) == out.end()) out.push_back(a);
  }
  freeaddrinfo(res);
  if (out.empty()) *error = "no IPv4 address";
  return out;
}

std::string interface_with_address(std::uint32_t local) {
  ifaddrs* list = nullptr;
  if (::getifaddrs(&list) != 0) return {};
  std::string name;
  for (const ifaddrs* p = list; p != nullptr && name.empty(); p = p->ifa_next) {
    if (p->ifa_addr == nullptr || p->ifa_addr->sa_family != AF_INET) continue;
    sockaddr_in a{};
    std::memcpy(&a, p->ifa_addr, sizeof a);
    if (ntohl(a.sin_addr.s_addr) == local) name = p->ifa_name;
  }
  ::freeifaddrs(list);
  return name;
}

}  // namespace lmc::devices::net
#endif
