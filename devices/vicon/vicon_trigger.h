#pragma once
// Sends the Vicon capture trigger over UDP (docs/algorithms/vicon.md): CaptureStart when all
// devices stream, CaptureStop at the end, each repeated (default 3 times, as the study did) with
// the same PacketID so a receiver keeps one; PacketIDs increase per message and are never reused
// across sessions (Nexus drops IDs it has seen): each ID is max(time-based base, last ID any
// trigger on this host used + 1), the last one kept in a small state file under a lock, so two
// sessions started in the same second (or two programs at once) still get different IDs.
// Unicast sockets are connected, so an ICMP "port unreachable" surfaces as an error on a later
// send instead of vanishing; every failure is reported, never ignored.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "devices/platform/udp_socket.h"
#include "devices/vicon/vicon_message.h"
#include "devices/vicon/vicon_senders.h"

namespace lmc::devices {

struct ViconTriggerConfig {
  std::string host = "255.255.255.255";  // unicast address/name or a broadcast address
  std::uint16_t port = 30;
  int repeats = 3;
  int repeat_interval_ms = 5;
  std::string database_path;
  std::string notes;
  std::string description;
  int delay_ms = 0;
  // Given: IDs are exactly first, first + 1, … and nothing is persisted (tests). Default: see
  // the top of this file.
  std::optional<std::uint32_t> first_packet_id;
  // Where the last PacketID used is kept; empty: default_packet_id_file().
  std::filesystem::path packet_id_file;
};

// $LMC_STATE_DIR/vicon-packet-id, else $XDG_STATE_HOME/lmc-workbench/vicon-packet-id, else
// ~/.local/state/lmc-workbench/vicon-packet-id; empty when none of these can be named.
std::filesystem::path default_packet_id_file();

// "HOST" or "HOST:PORT" (port default 30). Throws lmc::Error for a bad port.
ViconTriggerConfig parse_vicon_target(const std::string& spec);

struct ViconSendResult {
  ViconMessage message;
  int datagrams_sent = 0;
  std::int64_t first_datagram_host_ns = 0;  // host_now_ns() right after the first datagram left (0: none)
  std::string error;                        // empty when every repeat went out
  std::string warning;  // e.g. the PacketID state file could not be used (IDs then come from the clock only)
  bool ok() const { return error.empty(); }
};

class ViconTrigger {
 public:
  // Resolves the host and opens the socket; throws lmc::Error when that fails.
  explicit ViconTrigger(ViconTriggerConfig config);
  ~ViconTrigger();
  ViconTrigger(const ViconTrigger&) = delete;
  ViconTrigger& operator=(const ViconTrigger&) = delete;

  ViconSendResult send_start(const std::string& trial_name);
  ViconSendResult send_stop(const std::string& trial_name, bool cancel = false);
  ViconSendResult send(ViconMessage message);  // assigns the next PacketID

  const ViconTriggerConfig& config() const { return config_; }
  std::string target() const;

 private:
  ViconTriggerConfig config_;
  std::unique_ptr<net::UdpSocket> socket_;
  bool broadcast_ = false;
  std::uint32_t reserve_packet_id(std::string& warning);
  std::uint32_t next_id_ = 0;
  std::filesystem::path id_file_;
};

// Who sent a datagram (IPv4, host byte order).
struct ViconSender {
  std::uint32_t address = 0;
  std::uint16_t port = 0;
  std::string host() const;  // "10.0.0.5"
  std::string text() const;  // "10.0.0.5:51234"
};

// Datagrams from a sender the listener does not allow. Consecutive datagrams of one sender with
// the same content are one refusal (Vicon sends every message several times).
struct ViconRefusal {
  ViconSender sender;
  std::string what;  // "CaptureStart 'Trial01' (PacketID 7)", or "412 bytes, not a capture message"
  int datagrams = 0;
};

struct ViconListenerConfig {
  std::string bind_address = "0.0.0.0";  // "127.0.0.1" in tests
  std::string interface_name;            // tie the socket to this interface (vicon_route.h); empty: none
  std::uint16_t port = 30;               // 0 picks a free port (see port())
  ViconSenders allowed;                  // whose capture messages are obeyed; empty: any sender
};

// Listens for capture start/stop datagrams (Vicon's own broadcast, or our trigger in tests) and
// calls back once per PacketID (repeats are dropped). Runs its own thread. A datagram from a
// sender that is not allowed is refused before it is read: counted, kept for the owner to log
// (take_refusals) and never obeyed, whatever it says.
class ViconListener {
 public:
  using Callback = std::function<void(const ViconMessage&)>;
  using SenderCallback = std::function<void(const ViconMessage&, const ViconSender&)>;
  // Any sender; bind_address "127.0.0.1" in tests; port 0 picks a free port (see port()).
  ViconListener(const std::string& bind_address, std::uint16_t port, Callback callback);
  ViconListener(ViconListenerConfig config, SenderCallback callback);
  ~ViconListener();
  ViconListener(const ViconListener&) = delete;
  ViconListener& operator=(const ViconListener&) = delete;

  std::uint16_t port() const { return port_; }
  int datagrams_received() const { return received_.load(); }
  // Datagrams from allowed senders that are not capture messages.
  int rejected() const { return rejected_.load(); }
  // Why the latest rejected datagram was not a capture message, with its size ("412 bytes: …"),
  // so the operator learns what else is sending to the port.
  std::string last_rejection() const;
  // Datagrams from senders that are not allowed, in all and per sender address (the first
  // kMaxRefusedHosts addresses; later ones count in refused() only).
  std::int64_t refused() const { return refused_.load(); }
  std::vector<std::pair<std::string, std::int64_t>> refused_by_host() const;
  // The refusals since the previous call, oldest first (at most kMaxPendingRefusals are kept
  // between calls; *not_listed, when given, gets how many datagrams were left out).
  std::vector<ViconRefusal> take_refusals(std::int64_t* not_listed = nullptr);
  // Empty, or why the socket could not be tied to config.interface_name (it then listens on
  // every interface; the sender check still applies).
  const std::string& interface_note() const { return interface_note_; }

  static constexpr size_t kMaxRefusedHosts = 64;
  static constexpr size_t kMaxPendingRefusals = 256;

 private:
  void open(const ViconListenerConfig& config);
  void run();
  void refuse(const ViconSender& from, std::string_view datagram);
  std::unique_ptr<net::UdpSocket> socket_;
  std::uint16_t port_ = 0;
  ViconSenders allowed_;
  SenderCallback callback_;
  std::string interface_note_;
  std::atomic<bool> stop_{false};
  std::atomic<int> received_{0};
  std::atomic<int> rejected_{0};
  std::atomic<std::int64_t> refused_{0};
  mutable std::mutex rejection_mutex_;  // guards the four below
  std::string last_rejection_;
  std::vector<std::pair<std::string, std::int64_t>> refused_by_host_;
  std::vector<ViconRefusal> refusals_;
  std::int64_t refusals_not_listed_ = 0;
  std::thread thread_;
};

}  // namespace lmc::devices
