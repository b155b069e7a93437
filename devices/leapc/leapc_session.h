#pragma once
// One LeapC connection's life on the poll thread: the devices it opened, the ones waiting for a
// retry, and one handler per service event. LeapcSource (leapc_source.h) owns the thread; this
// class owns what the thread touches. Every handler copies what it needs out of the message; the
// poll loop runs the housekeeping that may close devices only after the message is done with,
// since closing a device may free the message the service handed over.
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "devices/frame_source.h"
#include "devices/leapc/leapc_library.h"
#include "devices/leapc/leapc_source.h"
#include "devices/tracking_mode.h"

namespace lmc::devices {

class LeapcSession {
 public:
  LeapcSession(std::shared_ptr<const LeapcLibrary> library, LeapcOptions options);
  ~LeapcSession();
  LeapcSession(const LeapcSession&) = delete;
  LeapcSession& operator=(const LeapcSession&) = delete;

  // Creates and opens the connection; throws lmc::Error when LeapC refuses.
  void open();
  // The poll loop, until stop_requested(); then closes every device. On the poll thread.
  void run(FrameSink& sink);
  // From any thread: ends run() soon, also when a poll blocks (the connection is closed under it).
  void request_stop();
  // From any thread: no event reaches the sink from now on (a stop() that gives up waiting).
  void silence() { silenced_ = true; }
  // After run() returned (or was abandoned and has returned since): destroys the connection.
  void destroy();
  const LeapcLibrary& library() const { return *library_; }

 private:
  static constexpr std::int64_t kMsNs = 1'000'000;
  static constexpr std::int64_t kDropIntervalNs = 1'000 * kMsNs;  // dropped frames: one message per device and second
  struct OpenDevice {
    leapc::Device handle = nullptr;
    std::string serial;
    std::string model;
    std::uint32_t product_id = 0;
    bool subscribed = false;  // announced (kAppeared) only from then on
    int subscribe_attempts = 0;
    std::int64_t retry_at_ns = 0;
    std::int64_t subscribed_ns = 0;
    TrackingMode wanted_mode = TrackingMode::kDesktop;
    TrackingMode mode = TrackingMode::kUnknown;  // as the service last reported it
    std::optional<bool> background_granted;      // the service's latest answer
    bool warned_background = false;
    bool warned_mode = false;
    std::int64_t drops_pending = 0;
    std::int64_t drops_reported_ns = 0;
  };
  struct PendingOpen {
    leapc::DeviceRef ref{};
    int attempts = 0;
    std::int64_t retry_at_ns = 0;
  };

  // Events out.
  void emit(DeviceEventKind kind, const std::string& serial, std::string message, std::int64_t count = 0);
  void say(std::string message) { emit(DeviceEventKind::kNotice, "", std::move(message)); }
  OpenDevice* find(std::uint32_t id);
  OpenDevice* find_subscribed(std::uint32_t id);

  // Devices.
  void open_or_queue(const leapc::DeviceRef& ref, std::int64_t now_ns);
  leapc::Result try_open(const leapc::DeviceRef& ref, std::int64_t now_ns);
  leapc::Result read_serial(leapc::Device handle, leapc::DeviceInfo& info, std::string& serial);
  bool refuse_duplicate(const leapc::DeviceRef& ref, leapc::Device handle, const std::string& serial);
  void try_subscribe(std::uint32_t id, OpenDevice& d, std::int64_t now_ns);
  void finish_setup(OpenDevice& d, std::int64_t now_ns);
  void close_device(std::uint32_t id);
  void lose_device(std::uint32_t id, const std::string& why, std::int64_t now_ns);
  void lose_all(const std::string& why, std::int64_t now_ns);
  void reconsider_refused(std::int64_t now_ns);
  void flush_drops(OpenDevice& d, std::int64_t now_ns);
  void check_warnings(OpenDevice& d, std::int64_t now_ns);
  void report_mode(OpenDevice& d, TrackingMode mode, std::int64_t now_ns);

  // The poll loop's parts.
  void housekeeping(std::int64_t now_ns);
  void on_poll_failure(leapc::Result rs);
  void watch_silent_service(std::int64_t now_ns);
  void handle(const leapc::ConnectionMessage& msg, std::int64_t now_ns);
  void on_connection(const leapc::ConnectionEvent* ev, std::int64_t now_ns);
  void on_device(const leapc::DeviceEvent* ev, std::int64_t now_ns);
  void on_device_lost(const leapc::DeviceEvent* ev, std::int64_t now_ns);
  void on_device_failure(const leapc::DeviceFailureEvent* ev, std::uint32_t device_id);
  void on_status_change(const leapc::DeviceStatusChangeEvent* ev, std::uint32_t device_id);
  void on_policy(const leapc::PolicyEvent* ev, std::uint32_t device_id, std::int64_t now_ns);
  void on_tracking_mode(const leapc::TrackingModeEvent* ev, std::uint32_t device_id, std::int64_t now_ns);
  void on_dropped_frame(std::uint32_t device_id, std::int64_t now_ns);
  void on_log(const leapc::LogEvent& ev);
  void on_tracking(const leapc::TrackingEvent* ev, std::uint32_t device_id, std::int64_t now_ns);

  std::shared_ptr<const LeapcLibrary> library_;
  const LeapcApi& api_;
  LeapcOptions options_;
  leapc::Connection connection_ = nullptr;
  FrameSink* sink_ = nullptr;
  std::atomic<bool> stop_{false};
  std::atomic<bool> silenced_{false};
  std::map<std::uint32_t, OpenDevice> devices_;        // by LEAP_DEVICE_REF.id
  std::map<std::uint32_t, PendingOpen> pending_;       // announced, not opened yet
  std::map<std::uint32_t, leapc::DeviceRef> refused_;  // refused for a duplicate serial, reconsidered when one goes
  // The service: whether it ever answered, when we began waiting, what was said.
  bool connected_ = false;
  bool told_unreachable_ = false;
  bool told_service_version_ = false;
  int consecutive_errors_ = 0;
  std::int64_t waiting_since_ns_ = 0;
};

}  // namespace lmc::devices
