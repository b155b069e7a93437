#include "devices/platform/udp_socket.h"

#ifdef _WIN32
#include <winsock2.h>
// After winsock2.h, which they need.
#include <iphlpapi.h>
#include <ws2tcpip.h>
#else
#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#endif

#include <algorithm>
#include <cstring>
#include <vector>

#include "core/common/error.h"
#include "core/platform/system_error.h"

namespace lmc::devices::net {
namespace {

// What differs between Winsock and BSD sockets, side by side; everything after this block is
// written once for both.
#ifdef _WIN32
using Native = SOCKET;
using AddressLength = int;
constexpr std::intptr_t kNoSocket = static_cast<std::intptr_t>(INVALID_SOCKET);

std::string socket_error() {
  return platform::system_error_text(WSAGetLastError());
}
void close_socket(Native s) {
  closesocket(s);
}
int wait_readable(Native s, int timeout_ms) {
  WSAPOLLFD p{};
  p.fd = s;
  p.events = POLLRDNORM;
  return WSAPoll(&p, 1, timeout_ms);
}

// Winsock must be started before any socket call; once per process, never stopped (the process's
// end cleans up), so a socket may outlive any object that started it.
bool start_sockets(std::string* error) {
  static const int started = [] {
    WSADATA data{};
    return WSAStartup(MAKEWORD(2, 2), &data);
  }();
  if (started != 0) *error = "Winsock did not start: " + platform::system_error_text(started);
  return started == 0;
}

Native open_native() {
  // Not inherited by programs this one starts (as SOCK_CLOEXEC on Linux).
  return WSASocketW(AF_INET, SOCK_DGRAM, IPPROTO_UDP, nullptr, 0, WSA_FLAG_NO_HANDLE_INHERIT);
}
#else
using Native = int;
using AddressLength = socklen_t;
constexpr std::intptr_t kNoSocket = -1;

std::string socket_error() {
  return platform::last_system_error();
}
void close_socket(Native s) {
  ::close(s);
}
int wait_readable(Native s, int timeout_ms) {
  pollfd p{s, POLLIN, 0};
  const int ready = ::poll(&p, 1, timeout_ms);
  return ready < 0 && errno == EINTR ? 0 : ready;
}
bool start_sockets(std::string*) {
  return true;
}
Native open_native() {
  return ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
}
#endif

Native native(std::intptr_t handle) {
  return static_cast<Native>(handle);
}

sockaddr_in endpoint(std::uint32_t address, std::uint16_t port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  a.sin_addr.s_addr = htonl(address);
  return a;
}

std::intptr_t open_socket(const std::string& who) {
  std::string why;
  if (!start_sockets(&why)) throw Error(who + ": cannot open a UDP socket: " + why);
  const auto s = static_cast<std::intptr_t>(open_native());
  if (s == kNoSocket) throw Error(who + ": cannot open a UDP socket: " + socket_error());
  return s;
}

}  // namespace

UdpSocket::UdpSocket(const std::string& who) : handle_(open_socket(who)) {}

UdpSocket::~UdpSocket() {
  if (handle_ != kNoSocket) close_socket(native(handle_));
}

UdpSocket::UdpSocket(UdpSocket&& other) noexcept : handle_(other.handle_), error_(std::move(other.error_)) {
  other.handle_ = kNoSocket;
}

void UdpSocket::fail() {
  error_ = socket_error();
}

bool UdpSocket::enable_broadcast() {
  const int on = 1;
  if (setsockopt(native(handle_), SOL_SOCKET, SO_BROADCAST, reinterpret_cast<const char*>(&on), sizeof on) == 0)
    return true;
  fail();
  return false;
}

void UdpSocket::claim_port() {
  const int on = 1;
#ifdef _WIN32
  setsockopt(native(handle_), SOL_SOCKET, SO_EXCLUSIVEADDRUSE, reinterpret_cast<const char*>(&on), sizeof on);
#else
  setsockopt(native(handle_), SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
#endif
}

bool UdpSocket::bind_to_interface(const std::string& name) {
#ifdef _WIN32
  (void)name;
  error_ = "Windows cannot tie a socket to one interface";
#else
  if (setsockopt(native(handle_), SOL_SOCKET, SO_BINDTODEVICE, name.c_str(), static_cast<socklen_t>(name.size())) == 0)
    return true;
  fail();
#endif
  return false;
}

bool UdpSocket::bind(std::uint32_t address, std::uint16_t port) {
  const sockaddr_in a = endpoint(address, port);
  if (::bind(native(handle_), reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0) return true;
  fail();
  return false;
}

bool UdpSocket::connect(std::uint32_t address, std::uint16_t port) {
  const sockaddr_in a = endpoint(address, port);
  if (::connect(native(handle_), reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0) return true;
  fail();
  return false;
}

std::optional<std::uint32_t> UdpSocket::local_address() {
  sockaddr_in local{};
  AddressLength len = sizeof local;
  if (getsockname(native(handle_), reinterpret_cast<sockaddr*>(&local), &len) == 0) return ntohl(local.sin_addr.s_addr);
  fail();
  return std::nullopt;
}

std::uint16_t UdpSocket::local_port() {
  sockaddr_in local{};
  AddressLength len = sizeof local;
  if (getsockname(native(handle_), reinterpret_cast<sockaddr*>(&local), &len) != 0) return 0;
  return ntohs(local.sin_port);
}

long long UdpSocket::send(std::string_view data) {
  // Winsock counts in int, BSD sockets in size_t; a datagram is far below either's limit.
  const auto send_once = [&] {
    return static_cast<long long>(::send(native(handle_), data.data(), static_cast<int>(data.size()), 0));
  };
  long long n = send_once();
#ifndef _WIN32
  while (n < 0 && errno == EINTR) n = send_once();
#endif
  if (n < 0) fail();
  return n;
}

long long UdpSocket::receive(char* buffer, std::size_t size, std::uint32_t* from_address, std::uint16_t* from_port,
                             int timeout_ms) {
  if (const int ready = wait_readable(native(handle_), timeout_ms); ready <= 0) {
    if (ready < 0) fail();
    return ready < 0 ? -1 : 0;
  }
  sockaddr_in from{};
  AddressLength from_len = sizeof from;
  const long long n =
      recvfrom(native(handle_), buffer, static_cast<int>(size), 0, reinterpret_cast<sockaddr*>(&from), &from_len);
  if (n < 0) {
#ifdef _WIN32
    // A datagram larger than the buffer, or an ICMP "port unreachable" for an earlier send, which
    // Windows reports on the next receive: neither ends listening.
    if (const int e = WSAGetLastError(); e == WSAEMSGSIZE || e == WSAECONNRESET) return 0;
#endif
    fail();
    return -1;
  }
  *from_address = ntohl(from.sin_addr.s_addr);
  *from_port = ntohs(from.sin_port);
  return n;
}

std::vector<std::uint32_t> resolve_ipv4(const std::string& name, bool numeric_only, std::string* error) {
  std::vector<std::uint32_t> out;
  if (!start_sockets(error)) return out;
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_DGRAM;
  if (numeric_only) hints.ai_flags = AI_NUMERICHOST;
  addrinfo* res = nullptr;
  if (const int rc = getaddrinfo(name.c_str(), nullptr, &hints, &res); rc != 0 || res == nullptr) {
#ifdef _WIN32
    *error = platform::system_error_text(rc);
#else
    *error = gai_strerror(rc);
#endif
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

#ifdef _WIN32
std::string interface_with_address(std::uint32_t local) {
  ULONG size = 16 * 1024;
  std::vector<unsigned char> buffer;
  ULONG rc = ERROR_BUFFER_OVERFLOW;
  for (int tries = 0; tries < 3 && rc == ERROR_BUFFER_OVERFLOW; ++tries) {
    buffer.resize(size);
    rc = GetAdaptersAddresses(AF_INET, GAA_FLAG_SKIP_ANYCAST | GAA_FLAG_SKIP_MULTICAST | GAA_FLAG_SKIP_DNS_SERVER,
                              nullptr, reinterpret_cast<IP_ADAPTER_ADDRESSES*>(buffer.data()), &size);
  }
  if (rc != NO_ERROR) return {};
  for (auto* a = reinterpret_cast<IP_ADAPTER_ADDRESSES*>(buffer.data()); a != nullptr; a = a->Next) {
    for (auto* u = a->FirstUnicastAddress; u != nullptr; u = u->Next) {
      if (u->Address.lpSockaddr == nullptr || u->Address.lpSockaddr->sa_family != AF_INET) continue;
      sockaddr_in in{};
      std::memcpy(&in, u->Address.lpSockaddr, sizeof in);
      if (ntohl(in.sin_addr.s_addr) != local) continue;
      // The adapter's friendly name ("Ethernet 2"), as UTF-8.
      const int n = WideCharToMultiByte(CP_UTF8, 0, a->FriendlyName, -1, nullptr, 0, nullptr, nullptr);
      std::string name(n > 0 ? static_cast<size_t>(n - 1) : 0, '\0');
      if (n > 1) WideCharToMultiByte(CP_UTF8, 0, a->FriendlyName, -1, name.data(), n, nullptr, nullptr);
      return name;
    }
  }
  return {};
}
#else
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
#endif

}  // namespace lmc::devices::net
