#pragma once
// Sends the Vicon capture trigger over UDP (reference-algorithms.md §7): CaptureStart when all
// devices stream, CaptureStop at the end, each repeated (default 3 times, as the study did) with
// the same PacketID so a receiver keeps one; PacketIDs increase per message and start from a
// time-based base so they are never reused across sessions (Nexus drops IDs it has seen).
// Unicast sockets are connected, so an ICMP "port unreachable" surfaces as an error on a later
// send instead of vanishing; every failure is reported, never ignored.
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <thread>

#include "devices/vicon/vicon_message.h"

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
  std::optional<std::uint32_t> first_packet_id;  // default: derived from the wall clock
};

// "HOST" or "HOST:PORT" (port default 30). Throws lmc::Error for a bad port.
ViconTriggerConfig parse_vicon_target(const std::string& spec);

struct ViconSendResult {
  ViconMessage message;
  int datagrams_sent = 0;
  std::string error;  // empty when every repeat went out
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
  int fd_ = -1;
  bool broadcast_ = false;
  std::uint32_t next_id_ = 0;
};

// Listens for capture start/stop datagrams (Vicon's own broadcast, or our trigger in tests) and
// calls back once per PacketID (repeats are dropped). Runs its own thread.
class ViconListener {
 public:
  using Callback = std::function<void(const ViconMessage&)>;
  // bind_address "127.0.0.1" in tests; port 0 picks a free port (see port()).
  ViconListener(const std::string& bind_address, std::uint16_t port, Callback callback);
  ~ViconListener();
  ViconListener(const ViconListener&) = delete;
  ViconListener& operator=(const ViconListener&) = delete;

  std::uint16_t port() const { return port_; }
  int datagrams_received() const { return received_.load(); }
  int rejected() const { return rejected_.load(); }

 private:
  void run();
  int fd_ = -1;
  std::uint16_t port_ = 0;
  Callback callback_;
  std::atomic<bool> stop_{false};
  std::atomic<int> received_{0};
  std::atomic<int> rejected_{0};
  std::thread thread_;
};

}  // namespace lmc::devices
