#include "devices/vicon/vicon_route.h"

#include <set>

#include "core/common/error.h"
#include "devices/platform/udp_socket.h"

namespace lmc::devices {

std::optional<std::uint32_t> local_address_towards(std::uint32_t remote, std::string* error) {
  try {
    net::UdpSocket probe("route probe");
    // Any port: connect() on UDP only picks the route, nothing is sent.
    if (!probe.connect(remote, 9)) {
      if (error) *error = probe.error();
      return std::nullopt;
    }
    const auto local = probe.local_address();
    if (!local && error) *error = probe.error();
    return local;
  } catch (const Error& e) {
    if (error) *error = e.what();
    return std::nullopt;
  }
}

std::string interface_with_address(std::uint32_t local) {
  return net::interface_with_address(local);
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
