#include "devices/vicon/vicon_route.h"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <set>

#include "core/common/error.h"

namespace lmc::devices {

std::optional<std::uint32_t> local_address_towards(std::uint32_t remote, std::string* error) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) {
    if (error) *error = std::string("cannot open a UDP socket: ") + std::strerror(errno);
    return std::nullopt;
  }
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(9);  // any port: connect() on UDP only picks the route, nothing is sent
  to.sin_addr.s_addr = htonl(remote);
  std::optional<std::uint32_t> out;
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&to), sizeof to) != 0) {
    if (error) *error = std::strerror(errno);
  } else {
    sockaddr_in local{};
    socklen_t len = sizeof local;
    if (::getsockname(fd, reinterpret_cast<sockaddr*>(&local), &len) == 0) {
      out = ntohl(local.sin_addr.s_addr);
    } else if (error) {
      *error = std::strerror(errno);
    }
  }
  ::close(fd);
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

ViconListenBinding choose_vicon_listen_binding(const std::string& listen_address, const ViconSenders& senders) {
  ViconListenBinding b;
  if (!listen_address.empty()) {
    b.address = listen_address;
    b.note = "listening on " + listen_address + " as given";
    return b;
  }
  if (senders.any()) {
    b.note = "listening on every interface";
    return b;
  }
  // One probe per rule: a host itself, or the first host of a subnet. A rule spanning everything
  // (0.0.0.0/0) has no one route: every interface.
  std::set<std::string> interfaces;
  std::set<std::uint32_t> locals;
  for (const ViconSenderRule& r : senders.rules()) {
    if (r.prefix == 0) {
      b.note = "listening on every interface (" + r.text + " allows any sender)";
      return b;
    }
    const std::uint32_t probe = r.prefix >= 31 ? r.network : r.network + 1;
    std::string why;
    const auto local = local_address_towards(probe, &why);
    if (!local) throw Error("Vicon host " + r.text + " cannot be reached from this computer (" + why + ")");
    locals.insert(*local);
    // A host that is this computer (one of its own addresses) talks to it over loopback.
    interfaces.insert(interface_with_address(*local == probe ? 0x7F000001u : *local));
  }
  if (interfaces.size() != 1 || interfaces.begin()->empty()) {
    std::string names;
    for (const auto& n : interfaces) names += (names.empty() ? "" : ", ") + (n.empty() ? std::string("?") : n);
    b.note = "listening on every interface: the Vicon hosts are reached through " + names;
    return b;
  }
  b.interface_name = *interfaces.begin();
  if (locals.size() == 1) b.local_address = format_ipv4(*locals.begin());
  b.note = "listening on " + b.interface_name + (b.local_address.empty() ? "" : " (" + b.local_address + ")") +
           ", the interface that reaches " + senders.describe();
  return b;
}

}  // namespace lmc::devices
