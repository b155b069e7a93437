#include "devices/vicon/vicon_senders.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "core/common/error.h"
#include "devices/platform/udp_socket.h"

namespace lmc::devices {
namespace {

std::string trim(std::string_view s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return std::string(s.substr(a, b - a));
}

std::uint32_t mask_of(int prefix) {
  return prefix == 0 ? 0u : ~std::uint32_t{0} << (32 - prefix);
}

bool digits_and_dots(std::string_view s) {
  return !s.empty() && s.find_first_not_of("0123456789.") == std::string_view::npos;
}

// Letters, digits, '-' and '.' (RFC 1123 host names); anything else is a typo, not a name.
bool host_name_chars(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.';
  });
}

}  // namespace

std::optional<std::uint32_t> parse_ipv4(std::string_view text) {
  std::uint32_t out = 0;
  int parts = 0;
  size_t i = 0;
  while (parts < 4) {
    if (i >= text.size() || !std::isdigit(static_cast<unsigned char>(text[i]))) return std::nullopt;
    unsigned value = 0;
    size_t digits = 0;
    // "010" is octal to inet_aton and ten to a reader: neither guess is made.
    if (text[i] == '0' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])))
      return std::nullopt;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
      value = value * 10 + static_cast<unsigned>(text[i] - '0');
      if (++digits > 3 || value > 255) return std::nullopt;
      ++i;
    }
    out = (out << 8) | value;
    ++parts;
    if (parts < 4) {
      if (i >= text.size() || text[i] != '.') return std::nullopt;
      ++i;
    }
  }
  if (i != text.size()) return std::nullopt;
  return out;
}

std::string format_ipv4(std::uint32_t a) {
  return std::to_string(a >> 24) + "." + std::to_string((a >> 16) & 0xFF) + "." + std::to_string((a >> 8) & 0xFF) +
         "." + std::to_string(a & 0xFF);
}

bool ViconSenderRule::matches(std::uint32_t address) const {
  return (address & mask_of(prefix)) == network;
}

std::vector<std::uint32_t> resolve_ipv4_host(const std::string& name) {
  std::string why;
  std::vector<std::uint32_t> out = net::resolve_ipv4(name, false, &why);
  if (out.empty()) {
    if (why == "no IPv4 address") throw Error("Vicon host '" + name + "' has no IPv4 address");
    throw Error("Vicon host '" + name + "' cannot be resolved: " + why);
  }
  return out;
}

ViconSenders ViconSenders::parse(const std::string& list, const Resolver& resolve) {
  const Resolver& lookup = resolve ? resolve : Resolver(resolve_ipv4_host);
  ViconSenders out;
  if (trim(list).empty()) return out;
  size_t from = 0;
  for (;;) {
    const size_t comma = list.find(',', from);
    const std::string entry =
        trim(std::string_view(list).substr(from, comma == std::string::npos ? std::string::npos : comma - from));
    const std::string where = "Vicon host list '" + list + "': ";
    if (entry.empty()) throw Error(where + "an entry is empty (entries are separated by commas)");
    if (entry.find(':') != std::string::npos) {
      throw Error(where + "'" + entry +
                  "' is not an IPv4 address, subnet or host name (IPv6 is not supported, and the "
                  "port is the "
                  "listen port, not part of the host)");
    }
    const size_t slash = entry.find('/');
    if (slash != std::string::npos) {
      const std::string addr = entry.substr(0, slash), bits = entry.substr(slash + 1);
      const auto a = parse_ipv4(addr);
      if (!a) throw Error(where + "'" + addr + "' in '" + entry + "' is not an IPv4 address");
      const bool numeric = !bits.empty() && bits.size() <= 2 &&
                           std::all_of(bits.begin(), bits.end(), [](char c) { return c >= '0' && c <= '9'; });
      const int prefix = numeric ? std::stoi(bits) : -1;
      if (prefix < 0 || prefix > 32) throw Error(where + "'" + entry + "': the prefix length must be 0 to 32");
      out.rules_.push_back({entry, *a & mask_of(prefix), prefix});
    } else if (digits_and_dots(entry)) {
      // Dotted numbers never go to a resolver: a typo such as 10.0.0.300 is an error, not a name.
      const auto a = parse_ipv4(entry);
      if (!a) throw Error(where + "'" + entry + "' is not an IPv4 address");
      out.rules_.push_back({entry, *a, 32});
    } else {
      if (!host_name_chars(entry)) throw Error(where + "'" + entry + "' is not an IPv4 address or host name");
      for (const std::uint32_t a : lookup(entry)) out.rules_.push_back({entry, a, 32});
    }
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return out;
}

bool ViconSenders::allows(std::uint32_t address) const {
  if (rules_.empty()) return true;
  return std::any_of(rules_.begin(), rules_.end(), [&](const ViconSenderRule& r) { return r.matches(address); });
}

std::string ViconSenders::describe() const {
  if (rules_.empty()) return "any sender";
  std::string out;
  for (size_t i = 0; i < rules_.size();) {
    const ViconSenderRule& r = rules_[i];
    if (!out.empty()) out += ", ";
    out += r.text;
    const bool name = r.text.find('/') == std::string::npos && !parse_ipv4(r.text);
    if (!name) {
      ++i;
      continue;
    }
    // A host name: every address it resolved to, once.
    out += " (";
    size_t j = i;
    for (; j < rules_.size() && rules_[j].text == r.text; ++j)
      out += (j == i ? "" : ", ") + format_ipv4(rules_[j].network);
    out += ")";
    i = j;
  }
  return out;
}

}  // namespace lmc::devices
