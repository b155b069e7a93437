// LeapcSession: opening, identifying, subscribing, losing and retrying devices, and the
// housekeeping between polls (leapc_session.h).
#include <utility>
#include <vector>

#include "devices/host_clock.h"
#include "devices/leapc/leapc_session.h"

namespace lmc::devices {
namespace {
std::uint32_t to_leap_mode(TrackingMode m) {
  if (m == TrackingMode::kScreenTop) return leapc::kModeScreenTop;
  if (m == TrackingMode::kHeadMounted) return leapc::kModeHmd;
  return leapc::kModeDesktop;
}
}  // namespace

void LeapcSession::open_or_queue(const leapc::DeviceRef& ref, std::int64_t now_ns) {
  PendingOpen& p = pending_[ref.id];
  p.ref = ref;
  const leapc::Result rs = try_open(ref, now_ns);
  if (rs == leapc::kSuccess) {
    pending_.erase(ref.id);
    return;
  }
  ++p.attempts;
  const std::string what =
      "LeapC: cannot open device " + std::to_string(ref.id) + " and read its serial (" + leapc_result_name(rs) + ")";
  if (p.attempts >= options_.max_attempts) {
    say(what + "; gave up after " + std::to_string(p.attempts) + " attempts: re-plug it");
    pending_.erase(ref.id);
    return;
  }
  if (p.attempts == 1) say(what + "; trying again");
  p.retry_at_ns = now_ns + static_cast<std::int64_t>(options_.retry_interval_ms) * kMsNs;
}

// The serial decides the slot, so a device whose serial cannot be read is not taken: a failed
// read is a failed open, tried again (it happens for a moment after a hot-plug).
leapc::Result LeapcSession::read_serial(leapc::Device handle, leapc::DeviceInfo& info, std::string& serial) {
  info = {};
  info.size = sizeof info;
  info.serial = nullptr;
  const leapc::Result first = api_.get_device_info(handle, &info);  // learns serial_length
  if (first != leapc::kSuccess && first != leapc::kInsufficientBuffer) return first;
  if (info.serial_length == 0) return leapc::kUnknownError;
  std::vector<char> buffer(info.serial_length + 1, '\0');
  info.serial = buffer.data();
  info.serial_length = static_cast<std::uint32_t>(buffer.size());
  if (const leapc::Result rs = api_.get_device_info(handle, &info); rs != leapc::kSuccess) return rs;
  serial = buffer.data();
  info.serial = nullptr;
  return serial.empty() ? leapc::kUnknownError : leapc::kSuccess;
}

leapc::Result LeapcSession::try_open(const leapc::DeviceRef& ref, std::int64_t now_ns) {
  leapc::Device handle = nullptr;
  if (const leapc::Result rs = api_.open_device(ref, &handle); rs != leapc::kSuccess) return rs;
  leapc::DeviceInfo info{};
  std::string serial;
  if (const leapc::Result rs = read_serial(handle, info, serial); rs != leapc::kSuccess) {
    api_.close_device(handle);
    return rs;
  }
  if (refuse_duplicate(ref, handle, serial)) return leapc::kSuccess;
  OpenDevice& d = devices_[ref.id];
  d.handle = handle;
  d.serial = serial;
  d.model = leapc_model_name(info.pid);
  d.product_id = info.pid;
  d.wanted_mode = tracking_mode_for_serial(options_.layout, serial);
  try_subscribe(ref.id, d, now_ns);
  return leapc::kSuccess;
}

// Two open devices with one serial (placeholder serials of services before 5.4): taking both
// would interleave two controllers in one slot. The refused one is tried again when a device goes.
bool LeapcSession::refuse_duplicate(const leapc::DeviceRef& ref, leapc::Device handle, const std::string& serial) {
  for (const auto& [other_id, other] : devices_) {
    if (other.serial != serial) continue;
    api_.close_device(handle);
    refused_[ref.id] = ref;
    say("LeapC: refused the controller with device id " + std::to_string(ref.id) + ": it reports serial " + serial +
        ", as device " + std::to_string(other_id) +
        " does. Two controllers cannot share one serial (one slot); update the Ultraleap service (5.4 or newer "
        "reports real serials), or unplug one of them");
    return true;
  }
  return false;
}

void LeapcSession::try_subscribe(std::uint32_t id, OpenDevice& d, std::int64_t now_ns) {
  const leapc::Result rs = api_.subscribe_events(connection_, d.handle);
  if (rs == leapc::kSuccess) {
    finish_setup(d, now_ns);
    return;
  }
  ++d.subscribe_attempts;
  const std::string what = "LeapC: controller " + d.serial + " (device " + std::to_string(id) +
                           ") cannot be subscribed to (" + leapc_result_name(rs) + ")";
  if (d.subscribe_attempts >= options_.max_attempts) {
    say(what + "; gave up after " + std::to_string(d.subscribe_attempts) +
        " attempts: it is not used (the Ultraleap service must be 5.4 or newer)");
    close_device(id);
    return;
  }
  if (d.subscribe_attempts == 1) say(what + "; trying again");
  d.retry_at_ns = now_ns + static_cast<std::int64_t>(options_.retry_interval_ms) * kMsNs;
}

// Subscribed at last: ask for background frames and the tracking mode (both answered by later
// events, judged after the grace period), then announce the device.
void LeapcSession::finish_setup(OpenDevice& d, std::int64_t now_ns) {
  d.subscribed = true;
  d.subscribed_ns = now_ns;
  const leapc::Result prs = options_.background_frames
                                ? api_.set_policy_flags_ex(connection_, d.handle, leapc::kPolicyBackgroundFrames, 0)
                                : leapc::kSuccess;
  const leapc::Result mrs = options_.request_tracking_mode
                                ? api_.set_tracking_mode_ex(connection_, d.handle, to_leap_mode(d.wanted_mode))
                                : leapc::kSuccess;
  // The mode in force is asked for too, so a listing that changes nothing learns it.
  if (api_.get_tracking_mode_ex != nullptr) api_.get_tracking_mode_ex(connection_, d.handle);
  if (sink_ != nullptr && !silenced_) {
    DeviceEvent e;
    e.kind = DeviceEventKind::kAppeared;
    e.info.serial = d.serial;
    e.info.backend = "leapc";
    e.info.model = d.model;
    e.info.product_id = d.product_id;
    e.host_time_ns = host_now_ns();
    sink_->on_device_event(e);
  }
  if (prs != leapc::kSuccess)
    emit(DeviceEventKind::kNotice, d.serial,
         "cannot set the background-frames policy (" + leapc_result_name(prs) +
             "); it may stop streaming while another window has focus");
  if (mrs != leapc::kSuccess)
    emit(DeviceEventKind::kNotice, d.serial,
         std::string("cannot request ") + tracking_mode_name(d.wanted_mode) + " tracking mode (" +
             leapc_result_name(mrs) + "); it tracks in whatever mode the service has for it");
}

void LeapcSession::close_device(std::uint32_t id) {
  auto it = devices_.find(id);
  if (it == devices_.end()) return;
  if (it->second.subscribed) api_.unsubscribe_events(connection_, it->second.handle);
  api_.close_device(it->second.handle);
  devices_.erase(it);
}

void LeapcSession::lose_device(std::uint32_t id, const std::string& why, std::int64_t now_ns) {
  OpenDevice* d = find(id);
  if (d == nullptr) return;
  const std::string serial = d->serial;
  const bool announced = d->subscribed;
  flush_drops(*d, now_ns);
  close_device(id);
  if (announced) emit(DeviceEventKind::kLost, serial, why);
}

void LeapcSession::lose_all(const std::string& why, std::int64_t now_ns) {
  std::vector<std::uint32_t> ids;
  for (const auto& [id, d] : devices_) ids.push_back(id);
  for (const std::uint32_t id : ids) lose_device(id, why, now_ns);
  pending_.clear();
  refused_.clear();
}

void LeapcSession::reconsider_refused(std::int64_t now_ns) {
  std::map<std::uint32_t, leapc::DeviceRef> refused;
  refused.swap(refused_);
  for (const auto& [id, ref] : refused) open_or_queue(ref, now_ns);
}

// The service's DroppedFrame events are said, not counted: the frames they name are missing from
// the image frame ids too, and the hub counts those gaps.
void LeapcSession::flush_drops(OpenDevice& d, std::int64_t now_ns) {
  if (d.drops_pending == 0) return;
  emit(DeviceEventKind::kNotice, d.serial,
       "the service dropped " + std::to_string(d.drops_pending) + (d.drops_pending == 1 ? " frame" : " frames") +
           " (counted in the frame-id gaps)");
  d.drops_pending = 0;
  d.drops_reported_ns = now_ns;
}

void LeapcSession::report_mode(OpenDevice& d, TrackingMode mode, std::int64_t now_ns) {
  if (mode == d.mode) return;
  d.mode = mode;
  if (mode == d.wanted_mode) d.warned_mode = false;
  DeviceEvent e;
  e.kind = DeviceEventKind::kTrackingMode;
  e.info.serial = d.serial;
  e.info.backend = "leapc";
  e.info.tracking_mode = tracking_mode_name(mode);
  e.host_time_ns = now_ns;
  if (sink_ != nullptr && !silenced_) sink_->on_device_event(e);
}

// A refusal or another mode is said only once the grace period after subscribing is over: the
// service first sends the policies and mode it had, and answers the requests later.
void LeapcSession::check_warnings(OpenDevice& d, std::int64_t now_ns) {
  if (!d.subscribed || now_ns - d.subscribed_ns < static_cast<std::int64_t>(options_.warning_grace_ms) * kMsNs) return;
  if (options_.background_frames && d.background_granted == false && !d.warned_background) {
    emit(DeviceEventKind::kNotice, d.serial,
         "the service refused the background-frames policy: it may stop streaming while another window has focus");
    d.warned_background = true;
  }
  if (options_.request_tracking_mode && d.mode != TrackingMode::kUnknown && d.mode != d.wanted_mode && !d.warned_mode) {
    d.warned_mode = true;
    if (sink_ == nullptr || silenced_) return;
    DeviceEvent e;
    e.kind = DeviceEventKind::kTrackingMode;
    e.info.serial = d.serial;
    e.info.backend = "leapc";
    e.info.tracking_mode = tracking_mode_name(d.mode);
    e.message = std::string("not the ") + tracking_mode_name(d.wanted_mode) +
                " mode its place in the layout needs: it tracks the hand under the wrong assumption (the control "
                "panel or another program may have set it)";
    e.host_time_ns = now_ns;
    sink_->on_device_event(e);
  }
}

// Between polls, after the message is done with: retries that are due, dropped frames that
// waited a second, warnings whose grace period is over.
void LeapcSession::housekeeping(std::int64_t now_ns) {
  std::vector<std::uint32_t> due;
  for (const auto& [id, p] : pending_)
    if (p.retry_at_ns <= now_ns) due.push_back(id);
  for (const std::uint32_t id : due)
    if (auto it = pending_.find(id); it != pending_.end()) open_or_queue(it->second.ref, now_ns);
  due.clear();
  for (const auto& [id, d] : devices_)
    if (!d.subscribed && d.retry_at_ns <= now_ns) due.push_back(id);
  for (const std::uint32_t id : due)
    if (OpenDevice* d = find(id)) try_subscribe(id, *d, now_ns);
  for (auto& [id, d] : devices_) {
    if (d.drops_pending > 0 && now_ns - d.drops_reported_ns >= kDropIntervalNs) flush_drops(d, now_ns);
    check_warnings(d, now_ns);
  }
}

}  // namespace lmc::devices
