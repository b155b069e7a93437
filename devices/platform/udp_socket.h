#pragma once
// An IPv4 UDP socket for the Vicon trigger, listener and route probe: one interface for BSD
// sockets (Linux) and Winsock 2 (Windows, started once per process); udp_socket.cpp keeps what
// differs side by side. Addresses are in host byte order, as ViconSender keeps them.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lmc::devices::net {

class UdpSocket {
 public:
  // Throws lmc::Error "<who>: cannot open a UDP socket: <why>".
  explicit UdpSocket(const std::string& who);
  ~UdpSocket();
  UdpSocket(UdpSocket&& other) noexcept;
  UdpSocket& operator=(UdpSocket&&) = delete;
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;

  // Each false return leaves the reason in error().
  bool enable_broadcast();
  // A listener's port: on Linux SO_REUSEADDR (a restarted listener binds at once). On Windows
  // SO_EXCLUSIVEADDRUSE instead: there SO_REUSEADDR would let another program bind the same port
  // and take the datagrams meant for this one; with it a second listener is refused, by name.
  void claim_port();
  // Linux: SO_BINDTODEVICE. Windows has no such option: false, saying so.
  bool bind_to_interface(const std::string& name);
  bool bind(std::uint32_t address, std::uint16_t port);
  bool connect(std::uint32_t address, std::uint16_t port);
  std::optional<std::uint32_t> local_address();
  std::uint16_t local_port();
  // The bytes sent (all of data or fewer), or -1.
  long long send(std::string_view data);
  // Waits up to timeout_ms for one datagram: its size, 0 when none came, -1 on an error.
  long long receive(char* buffer, std::size_t size, std::uint32_t* from_address, std::uint16_t* from_port,
                    int timeout_ms);
  const std::string& error() const { return error_; }

 private:
  void fail();
  std::intptr_t handle_;  // a descriptor on Linux, a SOCKET on Windows
  std::string error_;
};

// The IPv4 addresses of a host name (or of dotted numbers only, when numeric_only: never sent to
// a resolver, so a typo such as 300.1.1.1 fails). Empty with *error set when it cannot be resolved.
std::vector<std::uint32_t> resolve_ipv4(const std::string& name, bool numeric_only, std::string* error);

// The name of the interface holding this local address (Linux: "lo", "eth0"; Windows: the
// adapter's friendly name); empty when none does.
std::string interface_with_address(std::uint32_t local);

}  // namespace lmc::devices::net
