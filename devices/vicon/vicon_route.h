#pragma once
// Where a Vicon listener listens when the operator named the Vicon host(s) but no listen address:
// on the network interface that reaches them, found the way the kernel would route a reply (a UDP
// socket connected to the host, then getsockname: no packet leaves).
//
// The socket is bound to that interface (SO_BINDTODEVICE) at address 0.0.0.0, not to the
// interface's own address: a socket bound to 10.0.0.2 never receives datagrams sent to
// 10.0.0.255 or 255.255.255.255, and Vicon usually broadcasts its capture messages. The sender
// check (vicon_senders.h) is what keeps other hosts out; the interface keeps other networks out.
#include <cstdint>
#include <optional>
#include <string>

#include "devices/vicon/vicon_senders.h"

namespace lmc::devices {

struct ViconListenBinding {
  std::string address = "0.0.0.0";  // what the socket binds
  std::string interface_name;       // the interface it is tied to; empty: every interface
  std::string local_address;        // this host's address towards the Vicon host(s), when known
  std::string note;                 // how it was chosen, for the operator
};

// This host's address on the route to `remote` (host byte order); nullopt with *error set when
// there is no route.
std::optional<std::uint32_t> local_address_towards(std::uint32_t remote, std::string* error = nullptr);
// The name of the interface that holds `local` ("eth0", "lo"), or "" when none does.
std::string interface_with_address(std::uint32_t local);

// An explicit listen address is taken as given. Otherwise: with no allowed hosts, every
// interface; with hosts, the interface that routes to them all, or every interface (with a note)
// when they are reached through different ones. Throws lmc::Error naming the host when one is
// unreachable (no route from this computer).
ViconListenBinding choose_vicon_listen_binding(const std::string& listen_address, const ViconSenders& senders);

}  // namespace lmc::devices
