#include "devices/vicon/vicon_trigger.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <set>

#include "core/common/error.h"
#include "core/platform/file_lock.h"
#include "devices/host_clock.h"
#include "devices/platform/udp_socket.h"

namespace lmc::devices {
namespace {

bool looks_numeric(const std::string& host) {
  return !host.empty() && host.find_first_not_of("0123456789.") == std::string::npos;
}

constexpr std::uint32_t kMaxPacketId = 0x7FFFFFFF;  // kept positive for receivers that read an int

// Seconds since the epoch × 10, so IDs grow across sessions even without the state file.
std::uint32_t clock_packet_id() {
  const auto secs =
      std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  return static_cast<std::uint32_t>((secs * 10) & kMaxPacketId);
}

std::string env_or_empty(const char* name) {
  const char* v = std::getenv(name);
  return v == nullptr ? std::string() : std::string(v);
}

}  // namespace

std::filesystem::path default_packet_id_file() {
  if (const std::string d = env_or_empty("LMC_STATE_DIR"); !d.empty())
    return std::filesystem::path(d) / "vicon-packet-id";
  if (const std::string d = env_or_empty("XDG_STATE_HOME"); !d.empty())
    return std::filesystem::path(d) / "lmc-workbench" / "vicon-packet-id";
#ifdef _WIN32
  if (const std::string d = env_or_empty("LOCALAPPDATA"); !d.empty())
    return std::filesystem::path(d) / "lmc-workbench" / "vicon-packet-id";
#endif
  if (const std::string h = env_or_empty("HOME"); !h.empty())
    return std::filesystem::path(h) / ".local" / "state" / "lmc-workbench" / "vicon-packet-id";
  return {};
}

ViconTriggerConfig parse_vicon_target(const std::string& spec) {
  ViconTriggerConfig c;
  const size_t colon = spec.rfind(':');
  c.host = spec.substr(0, colon);
  if (colon != std::string::npos) {
    const std::string port = spec.substr(colon + 1);
    int value = -1;
    try {
      size_t used = 0;
      value = std::stoi(port, &used);
      if (used != port.size()) value = -1;
    } catch (const std::exception&) {
      value = -1;
    }
    if (value <= 0 || value > 65535) throw Error("--vicon: '" + port + "' is not a UDP port (1-65535)");
    c.port = static_cast<std::uint16_t>(value);
  }
  if (c.host.empty()) throw Error("--vicon: no host given (HOST or HOST:PORT)");
  return c;
}

ViconTrigger::ViconTrigger(ViconTriggerConfig config) : config_(std::move(config)) {
  std::string why;
  // Dotted numbers are never sent to a resolver: a typo such as 300.1.1.1 fails here.
  const auto addresses = net::resolve_ipv4(config_.host, looks_numeric(config_.host), &why);
  if (addresses.empty()) throw Error("Vicon trigger: cannot resolve host '" + config_.host + "': " + why);
  const std::uint32_t ip = addresses.front();
  socket_ = std::make_unique<net::UdpSocket>("Vicon trigger");
  broadcast_ = ip == 0xFFFFFFFFu || (ip & 0xFFu) == 0xFFu;
  if (broadcast_ && !socket_->enable_broadcast())
    throw Error("Vicon trigger: cannot enable broadcast: " + socket_->error());
  if (!socket_->connect(ip, config_.port))
    throw Error("Vicon trigger: cannot reach " + target() + ": " + socket_->error());
  if (config_.first_packet_id) {
    next_id_ = *config_.first_packet_id;
  } else {
    // Never reuse an ID (docs/algorithms/vicon.md): the clock gives a growing base, the state file the
    // IDs already used on this host (reserve_packet_id).
    next_id_ = clock_packet_id();
    id_file_ = config_.packet_id_file.empty() ? default_packet_id_file() : config_.packet_id_file;
  }
}

std::uint32_t ViconTrigger::reserve_packet_id(std::string& warning) {
  if (config_.first_packet_id || id_file_.empty()) return next_id_++;
  std::error_code ec;
  std::filesystem::create_directories(id_file_.parent_path(), ec);
  // One writer at a time: two programs triggering at once still get different IDs.
  std::string text;
  platform::LockedFile file;
  try {
    file = platform::LockedFile::open(id_file_, &text);
  } catch (const Error& e) {
    warning = "Vicon trigger: cannot use the PacketID file " + id_file_.string() + " (" + e.what() +
              "); PacketIDs come from the clock only and may repeat for sessions started in the same second";
    return next_id_++;
  }
  std::uint32_t id = next_id_;
  if (!text.empty()) {
    char* end = nullptr;
    const unsigned long long last = std::strtoull(text.c_str(), &end, 10);
    if (end != text.c_str() && last < kMaxPacketId && last + 1 > id) id = static_cast<std::uint32_t>(last + 1);
  }
  if (std::string why; !file.replace_text(std::to_string(id) + "\n", &why))
    warning = "Vicon trigger: cannot update the PacketID file " + id_file_.string() + " (" + why + ")";
  next_id_ = id >= kMaxPacketId ? 0 : id + 1;
  return id;
}

ViconTrigger::~ViconTrigger() = default;

std::string ViconTrigger::target() const {
  return config_.host + ":" + std::to_string(config_.port);
}

ViconSendResult ViconTrigger::send_start(const std::string& trial_name) {
  ViconMessage m;
  m.type = ViconMessage::Type::kStart;
  m.name = trial_name;
  m.notes = config_.notes;
  m.description = config_.description;
  m.database_path = config_.database_path;
  m.delay_ms = config_.delay_ms;
  return send(std::move(m));
}

ViconSendResult ViconTrigger::send_stop(const std::string& trial_name, bool cancel) {
  ViconMessage m;
  m.type = ViconMessage::Type::kStop;
  m.name = trial_name;
  m.database_path = config_.database_path;
  m.delay_ms = config_.delay_ms;
  m.result = cancel ? "CANCEL" : "SUCCESS";
  return send(std::move(m));
}

ViconSendResult ViconTrigger::send(ViconMessage message) {
  ViconSendResult result;
  message.packet_id = reserve_packet_id(result.warning);
  const std::string payload = format_vicon_message(message);
  result.message = std::move(message);
  for (int i = 0; i < std::max(1, config_.repeats); ++i) {
    if (i > 0 && config_.repeat_interval_ms > 0)
      std::this_thread::sleep_for(std::chrono::milliseconds(config_.repeat_interval_ms));
    const long long n = socket_->send(payload);
    if (n < 0) {
      result.error = "Vicon trigger: sending to " + target() + " failed: " + socket_->error();
      return result;
    }
    if (static_cast<size_t>(n) != payload.size()) {
      result.error = "Vicon trigger: short send to " + target();
      return result;
    }
    if (result.datagrams_sent == 0) result.first_datagram_host_ns = host_now_ns();
    ++result.datagrams_sent;
  }
  return result;
}

std::string ViconSender::host() const {
  return format_ipv4(address);
}
std::string ViconSender::text() const {
  return host() + ":" + std::to_string(port);
}

ViconListener::ViconListener(const std::string& bind_address, std::uint16_t port, Callback callback)
    : callback_([cb = std::move(callback)](const ViconMessage& m, const ViconSender&) { cb(m); }) {
  ViconListenerConfig config;
  config.bind_address = bind_address;
  config.port = port;
  open(config);
}

ViconListener::ViconListener(ViconListenerConfig config, SenderCallback callback)
    : allowed_(config.allowed), callback_(std::move(callback)) {
  open(config);
}

void ViconListener::open(const ViconListenerConfig& config) {
  const std::string& bind_address = config.bind_address;
  const std::uint16_t port = config.port;
  socket_ = std::make_unique<net::UdpSocket>("Vicon listener");
  socket_->claim_port();
  if (!config.interface_name.empty()) {
    // Needs no privilege on Linux 5.7 and later for an unbound socket; where it is refused (and
    // on Windows, which has no such option) the listener still works on every interface, and
    // the sender check still keeps others out.
    if (!socket_->bind_to_interface(config.interface_name)) {
      interface_note_ = "Vicon listener: cannot listen on " + config.interface_name + " alone (" + socket_->error() +
                        "); listening on every interface, obeying only " + allowed_.describe();
    }
  }
  const auto address = parse_ipv4(bind_address);
  if (!address) throw Error("Vicon listener: '" + bind_address + "' is not an IPv4 address");
  if (!socket_->bind(*address, port))
    throw Error("Vicon listener: cannot listen on " + bind_address + ":" + std::to_string(port) + ": " +
                socket_->error());
  port_ = socket_->local_port();
  thread_ = std::thread([this] { run(); });
}

ViconListener::~ViconListener() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

std::string ViconListener::last_rejection() const {
  std::lock_guard lock(rejection_mutex_);
  return last_rejection_;
}

std::vector<std::pair<std::string, std::int64_t>> ViconListener::refused_by_host() const {
  std::lock_guard lock(rejection_mutex_);
  return refused_by_host_;
}

std::vector<ViconRefusal> ViconListener::take_refusals(std::int64_t* not_listed) {
  std::lock_guard lock(rejection_mutex_);
  if (not_listed != nullptr) *not_listed = refusals_not_listed_;
  refusals_not_listed_ = 0;
  return std::exchange(refusals_, {});
}

void ViconListener::refuse(const ViconSender& from, std::string_view datagram) {
  ++refused_;
  // What it would have done, so the log says more than "something came": parsed for the log only.
  std::string why;
  const auto m = parse_vicon_message(datagram, &why);
  std::string what;
  if (m) {
    what = std::string(m->type == ViconMessage::Type::kStart ? "CaptureStart" : "CaptureStop") + " '" + m->name +
           "' (PacketID " + std::to_string(m->packet_id) + ")";
  } else {
    what = std::to_string(datagram.size()) + " bytes, not a capture message";
  }
  std::lock_guard lock(rejection_mutex_);
  const std::string host = from.host();
  auto it =
      std::find_if(refused_by_host_.begin(), refused_by_host_.end(), [&](const auto& e) { return e.first == host; });
  if (it != refused_by_host_.end()) {
    ++it->second;
  } else if (refused_by_host_.size() < kMaxRefusedHosts) {
    refused_by_host_.emplace_back(host, 1);
  }
  if (!refusals_.empty() && refusals_.back().sender.address == from.address &&
      refusals_.back().sender.port == from.port && refusals_.back().what == what) {
    ++refusals_.back().datagrams;
  } else if (refusals_.size() < kMaxPendingRefusals) {
    refusals_.push_back({from, std::move(what), 1});
  } else {
    ++refusals_not_listed_;
  }
}

void ViconListener::run() {
  std::set<std::uint32_t> seen;
  char buf[65536];
  while (!stop_) {
    ViconSender from{};
    const long long n = socket_->receive(buf, sizeof buf, &from.address, &from.port, 50);
    if (n <= 0) continue;
    ++received_;
    const std::string_view datagram(buf, static_cast<size_t>(n));
    if (!allowed_.allows(from.address)) {
      refuse(from, datagram);
      continue;
    }
    std::string why;
    auto m = parse_vicon_message(datagram, &why);
    if (!m) {
      {
        std::lock_guard lock(rejection_mutex_);
        last_rejection_ = std::to_string(n) + " bytes: " + why;
      }
      ++rejected_;
      continue;
    }
    if (!seen.insert(m->packet_id).second) continue;  // a repeat
    callback_(*m, from);
  }
}

}  // namespace lmc::devices
