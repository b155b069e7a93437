#pragma once
// Which hosts may start and stop a recording in Vicon listen mode. A listener on a lab network
// hears every machine that sends to its port — a second Vicon system broadcasting on the same
// port, a colleague's test script — and a CaptureStart from any of them would start, name or stop
// a subject's trial. The operator names the lab's Vicon instead: a comma-separated list of IPv4
// addresses ("10.0.0.5"), subnets ("10.0.0.0/24") and host names ("vicon-pc.lab", resolved once,
// when the list is parsed, to every IPv4 address it has). IPv6 is not supported: Vicon's
// trigger is IPv4 broadcast or unicast. An empty list allows any sender (the caller warns).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lmc::devices {

// Host byte order throughout.
std::optional<std::uint32_t> parse_ipv4(std::string_view text);  // strict dotted quad, nullopt otherwise
std::string format_ipv4(std::uint32_t address);

struct ViconSenderRule {
  std::string text;           // the list entry that gave it ("vicon-pc.lab", "10.0.0.0/24")
  std::uint32_t network = 0;  // masked to the prefix
  int prefix = 32;            // 32: one host

  bool matches(std::uint32_t address) const;
};

class ViconSenders {
 public:
  // A host name → its IPv4 addresses; throws lmc::Error when it has none.
  using Resolver = std::function<std::vector<std::uint32_t>(const std::string& name)>;

  ViconSenders() = default;  // any sender
  // Parses the list; throws lmc::Error naming the entry at fault (not an address, a bad prefix,
  // an IPv6 address, a port, a name that does not resolve).
  static ViconSenders parse(const std::string& list, const Resolver& resolve = {});

  bool any() const { return rules_.empty(); }
  bool allows(std::uint32_t address) const;
  const std::vector<ViconSenderRule>& rules() const { return rules_; }
  // As the operator wrote it, names with what they resolved to: "vicon-pc.lab (10.0.0.7),
  // 10.0.1.0/24"; "any sender" when empty.
  std::string describe() const;

 private:
  std::vector<ViconSenderRule> rules_;
};

// The system resolver (getaddrinfo, IPv4 only).
std::vector<std::uint32_t> resolve_ipv4_host(const std::string& name);

}  // namespace lmc::devices
