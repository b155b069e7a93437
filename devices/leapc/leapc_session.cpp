#include "devices/leapc/leapc_session.h"

#include <chrono>
#include <thread>
#include <utility>
#include <vector>

#include "core/common/error.h"
#include "devices/host_clock.h"
#include "devices/leapc/leapc_hand.h"

namespace lmc::devices {
namespace {

TrackingMode from_leap_mode(std::uint32_t m) {
  if (m == leapc::kModeDesktop) return TrackingMode::kDesktop;
  if (m == leapc::kModeHmd) return TrackingMode::kHeadMounted;
  if (m == leapc::kModeScreenTop) return TrackingMode::kScreenTop;
  return TrackingMode::kUnknown;
}

// The policy flags say the mode too: the optimisations a tracking-mode request sets.
TrackingMode mode_from_policy(std::uint32_t flags) {
  if ((flags & leapc::kPolicyOptimizeHmd) != 0) return TrackingMode::kHeadMounted;
  if ((flags & leapc::kPolicyOptimizeScreenTop) != 0) return TrackingMode::kScreenTop;
  return TrackingMode::kDesktop;
}

const char* severity_word(std::uint32_t s) {
  if (s == leapc::kLogCritical) return "critical";
  if (s == leapc::kLogWarning) return "warning";
  return "information";
}

}  // namespace

LeapcSession::LeapcSession(std::shared_ptr<const LeapcLibrary> library, LeapcOptions options)
    : library_(std::move(library)), api_(library_->api), options_(std::move(options)) {}

LeapcSession::~LeapcSession() {
  destroy();
}

void LeapcSession::open() {
  leapc::ConnectionConfig config{};
  config.size = sizeof config;
  config.flags = leapc::kConnectionConfigMultiDeviceAware;
  config.server_namespace = nullptr;
  leapc::Connection c = nullptr;
  if (const leapc::Result rs = api_.create_connection(&config, &c); rs != leapc::kSuccess)
    throw Error("LeapC: cannot create a connection (" + leapc_result_name(rs) + ")");
  if (const leapc::Result rs = api_.open_connection(c); rs != leapc::kSuccess) {
    api_.destroy_connection(c);
    throw Error("LeapC: cannot open the connection (" + leapc_result_name(rs) + ")");
  }
  connection_ = c;
}

void LeapcSession::request_stop() {
  stop_ = true;
  // A poll may block well past its timeout; closing the connection ends it (as Ultraleap's own
  // Unity connection does before joining its thread).
  if (connection_ != nullptr) api_.close_connection(connection_);
}

void LeapcSession::destroy() {
  if (connection_ == nullptr) return;
  api_.destroy_connection(connection_);
  connection_ = nullptr;
}

void LeapcSession::emit(DeviceEventKind kind, const std::string& serial, std::string message, std::int64_t count) {
  if (sink_ == nullptr || silenced_) return;
  DeviceEvent e;
  e.kind = kind;
  e.info.serial = serial;
  e.info.backend = "leapc";
  e.message = std::move(message);
  e.count = count;
  e.host_time_ns = host_now_ns();
  sink_->on_device_event(e);
}

LeapcSession::OpenDevice* LeapcSession::find(std::uint32_t id) {
  auto it = devices_.find(id);
  return it == devices_.end() ? nullptr : &it->second;
}

LeapcSession::OpenDevice* LeapcSession::find_subscribed(std::uint32_t id) {
  OpenDevice* d = find(id);
  return d != nullptr && d->subscribed ? d : nullptr;
}

void LeapcSession::run(FrameSink& sink) {
  sink_ = &sink;
  say(leapc_library_text(*library_) + " loaded");
  waiting_since_ns_ = host_now_ns();
  while (!stop_) {
    leapc::ConnectionMessage msg{};
    const leapc::Result rs = api_.poll_connection(connection_, options_.poll_timeout_ms, &msg);
    if (stop_) break;
    const std::int64_t now_ns = host_now_ns();
    if (rs == leapc::kSuccess) {
      consecutive_errors_ = 0;
      handle(msg, now_ns);  // done with the message before anything below may close a device
    } else if (rs == leapc::kTimeout) {
      watch_silent_service(now_ns);
    } else {
      on_poll_failure(rs);
    }
    housekeeping(host_now_ns());
  }
  const std::int64_t end_ns = host_now_ns();
  for (auto& [id, d] : devices_) flush_drops(d, end_ns);
  sink_ = nullptr;
  for (auto& [id, d] : devices_) {
    if (d.subscribed) api_.unsubscribe_events(connection_, d.handle);
    api_.close_device(d.handle);
  }
  devices_.clear();
  pending_.clear();
  refused_.clear();
}

void LeapcSession::on_poll_failure(leapc::Result rs) {
  // The service may not be running yet, or restarting: say so now and then, keep polling.
  if (consecutive_errors_++ % 50 == 0) {
    if (rs == leapc::kNotConnected || rs == leapc::kNotAvailable || rs == leapc::kHandshakeIncomplete) {
      say("waiting for the Ultraleap service (LeapC: " + leapc_result_name(rs) + "): is it installed and running?");
      told_unreachable_ = true;
    } else {
      say("LeapC poll failed: " + leapc_result_name(rs));
    }
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
}

// A service that is not running may make every poll time out instead of failing: ask LeapC how
// the connection stands once the wait has lasted, and name it.
void LeapcSession::watch_silent_service(std::int64_t now_ns) {
  if (connected_ || told_unreachable_ || api_.get_connection_info == nullptr) return;
  if (now_ns - waiting_since_ns_ < static_cast<std::int64_t>(options_.service_check_ms) * kMsNs) return;
  leapc::ConnectionInfo info{};
  info.size = sizeof info;
  if (api_.get_connection_info(connection_, &info) != leapc::kSuccess) return;
  if (info.status == leapc::kConnectionConnected) return;
  const char* state = info.status == leapc::kConnectionNotRunning            ? "not running"
                      : info.status == leapc::kConnectionHandshakeIncomplete ? "handshake incomplete"
                                                                             : "not connected";
  say(std::string("waiting for the Ultraleap service (LeapC connection status: ") + state +
      "): is it installed and running?");
  told_unreachable_ = true;
}

void LeapcSession::handle(const leapc::ConnectionMessage& msg, std::int64_t now_ns) {
  const void* ev = msg.event;
  switch (msg.type) {
    case leapc::event::kConnection:
      return on_connection(static_cast<const leapc::ConnectionEvent*>(ev), now_ns);
    case leapc::event::kConnectionLost:
      // Every device is gone until the service is back; it re-announces them then, with new ids.
      lose_all("connection to the Ultraleap service lost", now_ns);
      connected_ = false;
      waiting_since_ns_ = now_ns;
      return say("connection to the Ultraleap service lost; waiting for it to come back");
    case leapc::event::kDevice:
      return on_device(static_cast<const leapc::DeviceEvent*>(ev), now_ns);
    case leapc::event::kDeviceLost:
      return on_device_lost(static_cast<const leapc::DeviceEvent*>(ev), now_ns);
    case leapc::event::kDeviceFailure:
      return on_device_failure(static_cast<const leapc::DeviceFailureEvent*>(ev), msg.device_id);
    case leapc::event::kDeviceStatusChange:
      return on_status_change(static_cast<const leapc::DeviceStatusChangeEvent*>(ev), msg.device_id);
    case leapc::event::kPolicy:
      return on_policy(static_cast<const leapc::PolicyEvent*>(ev), msg.device_id, now_ns);
    case leapc::event::kTrackingMode:
      return on_tracking_mode(static_cast<const leapc::TrackingModeEvent*>(ev), msg.device_id, now_ns);
    case leapc::event::kDroppedFrame:
      return on_dropped_frame(msg.device_id, now_ns);
    case leapc::event::kLogEvent:
      if (ev != nullptr) on_log(*static_cast<const leapc::LogEvent*>(ev));
      return;
    case leapc::event::kLogEvents:
      if (const auto* logs = static_cast<const leapc::LogEvents*>(ev); logs != nullptr)
        for (std::uint32_t i = 0; i < logs->nEvents; ++i) on_log(logs->events[i]);
      return;
    case leapc::event::kTracking:
      return on_tracking(static_cast<const leapc::TrackingEvent*>(ev), msg.device_id, now_ns);
    default:
      return;
  }
}

void LeapcSession::on_connection(const leapc::ConnectionEvent* ev, std::int64_t now_ns) {
  const std::uint32_t flags = ev != nullptr ? ev->flags : 0;  // closing a device below frees the message
  // A Connection event while devices are open is a service that restarted without a
  // ConnectionLost: its handles are stale and it announces its devices afresh.
  if (!devices_.empty() || !pending_.empty()) lose_all("the Ultraleap service restarted", now_ns);
  connected_ = true;
  if (told_unreachable_) {
    say("connected to the Ultraleap service");
    told_unreachable_ = false;
  }
  if (!told_service_version_ && api_.get_version != nullptr) {
    leapc::Version v{};
    if (api_.get_version(connection_, leapc::kVersionServerLibrary, &v) == leapc::kSuccess) {
      say("Ultraleap service " + leapc_version_text(v));
      told_service_version_ = true;
    }
  }
  if (flags == 0) return;
  std::string what;
  if ((flags & leapc::kServiceLowFps) != 0) what += " low frame rate detected;";
  if ((flags & leapc::kServicePoorPerformancePause) != 0) what += " paused for poor performance;";
  if ((flags & leapc::kServiceTrackingErrorUnknown) != 0) what += " tracking error;";
  say("Ultraleap service:" + what);
}

void LeapcSession::on_device(const leapc::DeviceEvent* ev, std::int64_t now_ns) {
  if (ev == nullptr) return;
  const leapc::DeviceRef ref = ev->device;
  if (pending_.count(ref.id) != 0 || refused_.count(ref.id) != 0) return;  // its retry or refusal stands
  // Announced again while open: the service re-enumerated it and the old handle is stale.
  if (devices_.count(ref.id) != 0) lose_device(ref.id, "the service announced it again", now_ns);
  open_or_queue(ref, now_ns);
}

void LeapcSession::on_device_lost(const leapc::DeviceEvent* ev, std::int64_t now_ns) {
  if (ev == nullptr) return;
  const std::uint32_t id = ev->device.id;
  pending_.erase(id);
  refused_.erase(id);
  if (find(id) == nullptr) return;
  lose_device(id, "device lost", now_ns);
  // The controller refused for sharing its serial may be this one re-plugged (its Device event
  // came before this DeviceLost): it is tried again now that the serial is free.
  reconsider_refused(now_ns);
}

void LeapcSession::on_device_failure(const leapc::DeviceFailureEvent* ev, std::uint32_t device_id) {
  if (ev == nullptr) return;
  // The event names its device by handle (hDevice, "may be NULL"); else the message's id.
  const OpenDevice* failed = nullptr;
  if (ev->hDevice != nullptr)
    for (const auto& [id, d] : devices_)
      if (d.handle == ev->hDevice) failed = &d;
  if (failed == nullptr) failed = find(device_id);
  // A device not yet streaming has no row: its failure is a message of its own.
  if (failed != nullptr && !failed->subscribed) failed = nullptr;
  emit(failed != nullptr ? DeviceEventKind::kFailure : DeviceEventKind::kNotice, failed ? failed->serial : "",
       (failed ? "" : "a controller not streaming yet failed: ") + leapc_status_text(ev->status));
}

void LeapcSession::on_status_change(const leapc::DeviceStatusChangeEvent* ev, std::uint32_t device_id) {
  if (ev == nullptr) return;
  const OpenDevice* d = find_subscribed(ev->device.id != 0 ? ev->device.id : device_id);
  if (d == nullptr) return;  // reported once the device streams, through its own events
  // A device that starts streaming says so as it attaches: its Appeared event said it already.
  if (ev->last_status == 0 && ev->status == leapc::kStatusStreaming) return;
  const bool failure = (ev->status & leapc::kStatusUnknownFailure) == leapc::kStatusUnknownFailure;
  emit(failure ? DeviceEventKind::kFailure : DeviceEventKind::kNotice, d->serial,
       "status " + leapc_status_text(ev->last_status) + " → " + leapc_status_text(ev->status));
}

void LeapcSession::on_policy(const leapc::PolicyEvent* ev, std::uint32_t device_id, std::int64_t now_ns) {
  // Only answers naming one of our devices count: the connection-wide policies (device_id 0) are
  // not the ones this backend sets.
  OpenDevice* d = find_subscribed(device_id);
  if (ev == nullptr || d == nullptr) return;
  const bool granted = (ev->current_policy & leapc::kPolicyBackgroundFrames) != 0;
  const bool was_refused = d->warned_background;
  d->background_granted = granted;
  if (granted && was_refused) {
    emit(DeviceEventKind::kNotice, d->serial, "background-frames policy granted");
    d->warned_background = false;
  }
  report_mode(*d, mode_from_policy(ev->current_policy), now_ns);
  check_warnings(*d, now_ns);
}

void LeapcSession::on_tracking_mode(const leapc::TrackingModeEvent* ev, std::uint32_t device_id, std::int64_t now_ns) {
  OpenDevice* d = find_subscribed(device_id);
  if (ev == nullptr || d == nullptr) return;
  report_mode(*d, from_leap_mode(ev->current_tracking_mode), now_ns);
  check_warnings(*d, now_ns);
}

void LeapcSession::on_dropped_frame(std::uint32_t device_id, std::int64_t now_ns) {
  OpenDevice* d = find_subscribed(device_id);
  if (d == nullptr) return;
  ++d->drops_pending;
  if (now_ns - d->drops_reported_ns >= kDropIntervalNs) flush_drops(*d, now_ns);
}

void LeapcSession::on_log(const leapc::LogEvent& ev) {
  if (ev.message == nullptr) return;
  say(std::string("Ultraleap service (") + severity_word(ev.severity) + "): " + ev.message);
}

void LeapcSession::on_tracking(const leapc::TrackingEvent* ev, std::uint32_t device_id, std::int64_t now_ns) {
  const OpenDevice* d = find_subscribed(device_id);
  if (ev == nullptr || d == nullptr || sink_ == nullptr || silenced_) return;  // not one of ours
  SourceFrame f = leapc_frame(*ev, options_.wanted_hand);
  f.serial = d->serial;
  f.host_receive_ns = now_ns;
  sink_->on_frame(f);
}

}  // namespace lmc::devices
