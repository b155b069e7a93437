// The LeapC test double's behaviour (see fake_leapc.h). Written from the public API reference.
#include "fake_leapc.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <thread>

struct _LEAP_CONNECTION {
  bool open = false;
};
struct _LEAP_DEVICE {
  std::uint32_t id = 0;
  std::string serial;
};

namespace fake_leapc {
namespace {

struct Queued {
  eLeapEventType type = eLeapEventType_None;
  std::uint32_t device_id = 0;  // message device_id (0 = system-wide)
  LEAP_DEVICE_EVENT device{};
  LEAP_DEVICE_FAILURE_EVENT failure{};
  LEAP_DEVICE_STATUS_CHANGE_EVENT status{};
  LEAP_DROPPED_FRAME_EVENT dropped{};
  LEAP_CONNECTION_EVENT connection{};
  LEAP_CONNECTION_LOST_EVENT lost{};
  LEAP_POLICY_EVENT policy{};
  LEAP_TRACKING_MODE_EVENT mode{};
  LEAP_TRACKING_EVENT tracking{};
  std::vector<LEAP_HAND> hands;
};

struct Failing {
  int times = 0;
  eLeapRS rs = eLeapRS_Success;
};

struct PluggedDevice {
  std::string serial;
  eLeapDevicePID pid = eLeapDevicePID_Peripheral;
  eLeapTrackingMode mode = eLeapTrackingMode_Desktop;
};

struct State {
  std::mutex mutex;
  std::condition_variable cv;
  std::deque<std::unique_ptr<Queued>> queue;
  std::unique_ptr<Queued> current;  // the message the client holds until its next poll
  std::map<std::uint32_t, PluggedDevice> plugged;
  std::set<std::uint32_t> subscribed;
  std::map<std::uint32_t, LEAP_DEVICE> opened;           // the client's open handles by device id
  std::map<std::uint32_t, std::uint64_t> device_policy;  // LeapSetPolicyFlagsEx, by device id
  std::map<std::uint32_t, eLeapRS> policy_ex_result;     // injected failures
  std::map<std::uint32_t, std::uint64_t> refused_policy;
  std::map<std::uint32_t, eLeapTrackingMode> held_mode;
  std::map<std::uint32_t, int> requested_mode;
  std::map<std::uint32_t, Failing> failing_open, failing_subscribe;
  std::map<std::uint32_t, std::int64_t> tracking_frame_id;
  int not_connected_polls = 0;
  std::int64_t clock_offset_us = 0;
  Stats stats;
  std::atomic<int> polling{0};
};

State& state() {
  static State s;
  return s;
}

void push_locked(std::unique_ptr<Queued> q) {
  state().queue.push_back(std::move(q));
}

void push(std::unique_ptr<Queued> q) {
  State& s = state();
  {
    std::lock_guard lock(s.mutex);
    push_locked(std::move(q));
  }
  s.cv.notify_all();
}

void push_mode_locked(std::uint32_t id, eLeapTrackingMode mode) {
  auto q = std::make_unique<Queued>();
  q->type = eLeapEventType_TrackingMode;
  q->device_id = id;
  q->mode.current_tracking_mode = mode;
  push_locked(std::move(q));
}

// One injected failure used up, or eLeapRS_Success.
eLeapRS take_failure(std::map<std::uint32_t, Failing>& failing, std::uint32_t id) {
  auto it = failing.find(id);
  if (it == failing.end() || it->second.times <= 0) return eLeapRS_Success;
  --it->second.times;
  return it->second.rs;
}

LEAP_VECTOR vec(float x, float y, float z) {
  LEAP_VECTOR v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}

}  // namespace

void reset() {
  State& s = state();
  std::lock_guard lock(s.mutex);
  s.queue.clear();
  s.current.reset();
  s.plugged.clear();
  s.subscribed.clear();
  s.opened.clear();
  s.device_policy.clear();
  s.policy_ex_result.clear();
  s.refused_policy.clear();
  s.held_mode.clear();
  s.requested_mode.clear();
  s.failing_open.clear();
  s.failing_subscribe.clear();
  s.tracking_frame_id.clear();
  s.not_connected_polls = 0;
  s.clock_offset_us = 0;
  s.stats = {};
}

void plug(std::uint32_t id, const std::string& serial, eLeapDevicePID pid, eLeapTrackingMode mode) {
  {
    std::lock_guard lock(state().mutex);
    state().plugged[id] = {serial, pid, mode};
  }
  auto q = std::make_unique<Queued>();
  q->type = eLeapEventType_Device;
  q->device.device.id = id;
  q->device.device.handle = reinterpret_cast<void*>(static_cast<std::uintptr_t>(id) * 16);
  q->device.status = eLeapDeviceStatus_Streaming;
  push(std::move(q));
}

void unplug(std::uint32_t id) {
  auto q = std::make_unique<Queued>();
  q->type = eLeapEventType_DeviceLost;
  q->device.device.id = id;
  push(std::move(q));
}

void device_failure(std::uint32_t id, eLeapDeviceStatus status, bool with_handle, bool with_message_device_id) {
  auto q = std::make_unique<Queued>();
  q->type = eLeapEventType_DeviceFailure;
  q->device_id = with_message_device_id ? id : 0;
  q->failure.status = status;
  q->failure.hDevice = nullptr;  // "may be NULL" per the reference
  if (with_handle) {
    std::lock_guard lock(state().mutex);
    auto it = state().opened.find(id);
    if (it != state().opened.end()) q->failure.hDevice = it->second;
  }
  push(std::move(q));
}

void fail_policy_ex(std::uint32_t id, eLeapRS rs) {
  std::lock_guard lock(state().mutex);
  if (rs == eLeapRS_Success)
    state().policy_ex_result.erase(id);
  else
    state().policy_ex_result[id] = rs;
}

void refuse_policy(std::uint32_t id, std::uint64_t flags) {
  std::lock_guard lock(state().mutex);
  state().refused_policy[id] = flags;
}

std::uint64_t device_policy(std::uint32_t id) {
  std::lock_guard lock(state().mutex);
  auto it = state().device_policy.find(id);
  return it == state().device_policy.end() ? 0 : it->second;
}

void hold_tracking_mode(std::uint32_t id, eLeapTrackingMode mode) {
  std::lock_guard lock(state().mutex);
  state().held_mode[id] = mode;
}

void change_tracking_mode(std::uint32_t id, eLeapTrackingMode mode) {
  {
    std::lock_guard lock(state().mutex);
    state().plugged[id].mode = mode;
    push_mode_locked(id, mode);
  }
  state().cv.notify_all();
}

int requested_tracking_mode(std::uint32_t id) {
  std::lock_guard lock(state().mutex);
  auto it = state().requested_mode.find(id);
  return it == state().requested_mode.end() ? -1 : it->second;
}

void fail_open(std::uint32_t id, int times, eLeapRS rs) {
  std::lock_guard lock(state().mutex);
  state().failing_open[id] = {times, rs};
}

void fail_subscribe(std::uint32_t id, int times, eLeapRS rs) {
  std::lock_guard lock(state().mutex);
  state().failing_subscribe[id] = {times, rs};
}

void not_connected_polls(int polls) {
  std::lock_guard lock(state().mutex);
  state().not_connected_polls = polls;
}

void status_change(std::uint32_t id, std::uint32_t last_status, std::uint32_t status) {
  auto q = std::make_unique<Queued>();
  q->type = eLeapEventType_DeviceStatusChange;
  q->device_id = id;
  q->status.device.id = id;
  q->status.last_status = last_status;
  q->status.status = status;
  push(std::move(q));
}

void dropped_frame(std::uint32_t id, std::int64_t frame_id) {
  auto q = std::make_unique<Queued>();
  q->type = eLeapEventType_DroppedFrame;
  q->device_id = id;
  q->dropped.frame_id = frame_id;
  q->dropped.type = eLeapDroppedFrameType_TrackingQueue;
  push(std::move(q));
}

void connection_lost() {
  auto q = std::make_unique<Queued>();
  q->type = eLeapEventType_ConnectionLost;
  push(std::move(q));
}

void connection_event(std::uint32_t flags) {
  auto q = std::make_unique<Queued>();
  q->type = eLeapEventType_Connection;
  q->connection.flags = flags;
  push(std::move(q));
}

void track(std::uint32_t id, std::int64_t frame_id, std::int64_t timestamp_us, float framerate,
           const std::vector<LEAP_HAND>& hands) {
  auto q = std::make_unique<Queued>();
  q->type = eLeapEventType_Tracking;
  q->device_id = id;
  q->hands = hands;
  q->tracking.info.frame_id = frame_id;
  q->tracking.info.timestamp = timestamp_us;
  q->tracking.framerate = framerate;
  {
    std::lock_guard lock(state().mutex);
    q->tracking.tracking_frame_id = ++state().tracking_frame_id[id];
    push_locked(std::move(q));
  }
  state().cv.notify_all();
}

LEAP_HAND make_hand(eLeapHandType type, float base) {
  LEAP_HAND h;
  std::memset(&h, 0, sizeof h);
  h.id = 1;
  h.type = type;
  h.confidence = 1.0F;
  h.palm.position = vec(base, base + 0.5F, base + 0.25F);
  h.palm.normal = vec(0, -1, 0);
  h.palm.direction = vec(0, 0, -1);
  h.arm.prev_joint = vec(base + 1, 0, 0);
  h.arm.next_joint = vec(base + 2, 0, 0);
  for (int d = 0; d < 5; ++d) {
    const float k = base + 3 + 5.0F * static_cast<float>(d);
    h.digits[d].finger_id = d;
    h.digits[d].bones[0].prev_joint = vec(k, 0, 0);
    for (int b = 0; b < 4; ++b) h.digits[d].bones[b].next_joint = vec(k + 1 + static_cast<float>(b), 0, 0);
    for (int b = 1; b < 4; ++b) h.digits[d].bones[b].prev_joint = h.digits[d].bones[b - 1].next_joint;
  }
  return h;
}

void set_clock_offset_us(std::int64_t offset) {
  std::lock_guard lock(state().mutex);
  state().clock_offset_us = offset;
}

std::int64_t now_us() {
  return LeapGetNow();
}

Stats stats() {
  State& s = state();
  std::lock_guard lock(s.mutex);
  Stats out = s.stats;
  out.pending = static_cast<int>(s.queue.size());
  return out;
}

}  // namespace fake_leapc

using fake_leapc::Queued;
using fake_leapc::state;

extern "C" {

eLeapRS LeapCreateConnection(const LEAP_CONNECTION_CONFIG* config, LEAP_CONNECTION* out) {
  if (out == nullptr) return eLeapRS_InvalidArgument;
  std::lock_guard lock(state().mutex);
  ++state().stats.connections_created;
  if (config != nullptr && (config->flags & eLeapConnectionConfig_MultiDeviceAware) != 0)
    ++state().stats.multi_device_aware;
  *out = new _LEAP_CONNECTION();
  return eLeapRS_Success;
}

eLeapRS LeapOpenConnection(LEAP_CONNECTION c) {
  if (c == nullptr) return eLeapRS_InvalidArgument;
  c->open = true;
  std::lock_guard lock(state().mutex);
  ++state().stats.connections_opened;
  return eLeapRS_Success;
}

void LeapCloseConnection(LEAP_CONNECTION c) {
  if (c != nullptr) c->open = false;
}

void LeapDestroyConnection(LEAP_CONNECTION c) {
  std::lock_guard lock(state().mutex);
  state().current.reset();
  delete c;
}

eLeapRS LeapSetPolicyFlags(LEAP_CONNECTION c, uint64_t set, uint64_t clear) {
  if (c == nullptr) return eLeapRS_InvalidArgument;
  std::lock_guard lock(state().mutex);
  state().stats.policy_set = (state().stats.policy_set | set) & ~clear;
  return eLeapRS_Success;
}

eLeapRS LeapSetPolicyFlagsEx(LEAP_CONNECTION c, LEAP_DEVICE d, uint64_t set, uint64_t clear) {
  if (c == nullptr || d == nullptr) return eLeapRS_InvalidArgument;
  {
    std::lock_guard lock(state().mutex);
    auto& s = state();
    ++s.stats.policy_ex_calls;
    if (auto it = s.policy_ex_result.find(d->id); it != s.policy_ex_result.end()) return it->second;
    auto& flags = s.device_policy[d->id];
    flags = (flags | set) & ~clear;
    if (auto it = s.refused_policy.find(d->id); it != s.refused_policy.end()) flags &= ~it->second;
    // The request is accepted; what the service made of it arrives later, as a Policy event.
    auto q = std::make_unique<Queued>();
    q->type = eLeapEventType_Policy;
    q->device_id = d->id;
    q->policy.current_policy = static_cast<uint32_t>(flags);
    fake_leapc::push_locked(std::move(q));
  }
  state().cv.notify_all();
  return eLeapRS_Success;
}

eLeapRS LeapSetTrackingModeEx(LEAP_CONNECTION c, LEAP_DEVICE d, eLeapTrackingMode mode) {
  if (c == nullptr || d == nullptr) return eLeapRS_InvalidArgument;
  {
    std::lock_guard lock(state().mutex);
    auto& s = state();
    ++s.stats.tracking_mode_calls;
    s.requested_mode[d->id] = mode;
    auto& device = s.plugged[d->id];
    auto held = s.held_mode.find(d->id);
    device.mode = held != s.held_mode.end() ? held->second : mode;
    fake_leapc::push_mode_locked(d->id, device.mode);
  }
  state().cv.notify_all();
  return eLeapRS_Success;
}

eLeapRS LeapGetTrackingModeEx(LEAP_CONNECTION c, LEAP_DEVICE d) {
  if (c == nullptr || d == nullptr) return eLeapRS_InvalidArgument;
  {
    std::lock_guard lock(state().mutex);
    ++state().stats.tracking_mode_queries;
    fake_leapc::push_mode_locked(d->id, state().plugged[d->id].mode);
  }
  state().cv.notify_all();
  return eLeapRS_Success;
}

eLeapRS LeapPollConnection(LEAP_CONNECTION c, uint32_t timeout, LEAP_CONNECTION_MESSAGE* evt) {
  auto& s = state();
  if (c == nullptr || evt == nullptr) return eLeapRS_InvalidArgument;
  if (s.polling.fetch_add(1) != 0) {
    s.polling.fetch_sub(1);
    std::lock_guard lock(s.mutex);
    ++s.stats.concurrent_polls;
    return eLeapRS_ConcurrentPoll;
  }
  std::unique_lock lock(s.mutex);
  s.current.reset();  // the previous message's pointers die here, as documented
  std::memset(evt, 0, sizeof *evt);
  evt->size = sizeof *evt;
  evt->type = eLeapEventType_None;
  if (s.not_connected_polls > 0) {
    // No service yet: LeapC answers at once, nothing is delivered. Once the service is up, the
    // first message is the Connection event.
    if (--s.not_connected_polls == 0) {
      auto q = std::make_unique<Queued>();
      q->type = eLeapEventType_Connection;
      s.queue.push_front(std::move(q));
    }
    s.polling.fetch_sub(1);
    return eLeapRS_NotConnected;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout);
  for (;;) {
    while (!s.queue.empty()) {
      auto q = std::move(s.queue.front());
      s.queue.pop_front();
      if (q->type == eLeapEventType_Tracking && s.subscribed.count(q->device_id) == 0) {
        ++s.stats.tracking_suppressed;
        continue;
      }
      if (q->type == eLeapEventType_Tracking) {
        ++s.stats.tracking_delivered;
        q->tracking.nHands = static_cast<uint32_t>(q->hands.size());
        q->tracking.pHands = q->hands.empty() ? nullptr : q->hands.data();
      }
      if (q->type == eLeapEventType_DeviceLost) s.subscribed.erase(q->device.device.id);
      evt->type = q->type;
      evt->device_id = q->device_id;
      switch (q->type) {
        case eLeapEventType_Device:
        case eLeapEventType_DeviceLost:
          evt->device_event = &q->device;
          break;
        case eLeapEventType_DeviceFailure:
          evt->device_failure_event = &q->failure;
          break;
        case eLeapEventType_DeviceStatusChange:
          evt->device_status_change_event = &q->status;
          break;
        case eLeapEventType_DroppedFrame:
          evt->dropped_frame_event = &q->dropped;
          break;
        case eLeapEventType_Connection:
          evt->connection_event = &q->connection;
          break;
        case eLeapEventType_ConnectionLost:
          evt->connection_lost_event = &q->lost;
          break;
        case eLeapEventType_Policy:
          evt->policy_event = &q->policy;
          break;
        case eLeapEventType_TrackingMode:
          evt->tracking_mode_event = &q->mode;
          break;
        case eLeapEventType_Tracking:
          evt->tracking_event = &q->tracking;
          break;
        default:
          break;
      }
      s.current = std::move(q);
      s.polling.fetch_sub(1);
      return eLeapRS_Success;
    }
    if (s.cv.wait_until(lock, deadline) == std::cv_status::timeout && s.queue.empty()) break;
  }
  s.polling.fetch_sub(1);
  return eLeapRS_Timeout;
}

eLeapRS LeapOpenDevice(LEAP_DEVICE_REF ref, LEAP_DEVICE* out) {
  if (out == nullptr) return eLeapRS_InvalidArgument;
  std::lock_guard lock(state().mutex);
  auto& s = state();
  ++s.stats.open_attempts;
  auto it = s.plugged.find(ref.id);
  if (it == s.plugged.end()) return eLeapRS_CannotOpenDevice;
  if (const eLeapRS rs = fake_leapc::take_failure(s.failing_open, ref.id); rs != eLeapRS_Success) return rs;
  ++s.stats.devices_opened;
  *out = new _LEAP_DEVICE{ref.id, it->second.serial};
  s.opened[ref.id] = *out;
  return eLeapRS_Success;
}

void LeapCloseDevice(LEAP_DEVICE d) {
  if (d == nullptr) return;
  {
    std::lock_guard lock(state().mutex);
    ++state().stats.devices_closed;
    if (auto it = state().opened.find(d->id); it != state().opened.end() && it->second == d) state().opened.erase(it);
  }
  delete d;
}

eLeapRS LeapGetDeviceInfo(LEAP_DEVICE d, LEAP_DEVICE_INFO* info) {
  if (d == nullptr || info == nullptr || info->size != sizeof(LEAP_DEVICE_INFO)) return eLeapRS_InvalidArgument;
  const auto needed = static_cast<uint32_t>(d->serial.size() + 1);
  info->status = eLeapDeviceStatus_Streaming;
  {
    std::lock_guard lock(state().mutex);
    auto it = state().plugged.find(d->id);
    info->pid = it == state().plugged.end() ? eLeapDevicePID_Unknown : it->second.pid;
  }
  info->baseline = 40000;
  info->h_fov = 2.618F;
  info->v_fov = 2.094F;
  info->range = 600000;
  // As documented: with serial == NULL (or too short a buffer) the call reports the length.
  if (info->serial == nullptr || info->serial_length < needed) {
    info->serial_length = needed;
    return info->serial == nullptr ? eLeapRS_Success : eLeapRS_InsufficientBuffer;
  }
  std::memcpy(info->serial, d->serial.c_str(), needed);
  info->serial_length = needed;
  return eLeapRS_Success;
}

eLeapRS LeapSubscribeEvents(LEAP_CONNECTION c, LEAP_DEVICE d) {
  if (c == nullptr || d == nullptr) return eLeapRS_InvalidArgument;
  std::lock_guard lock(state().mutex);
  auto& s = state();
  ++s.stats.subscribe_attempts;
  if (const eLeapRS rs = fake_leapc::take_failure(s.failing_subscribe, d->id); rs != eLeapRS_Success) return rs;
  ++s.stats.subscribed;
  s.subscribed.insert(d->id);
  return eLeapRS_Success;
}

eLeapRS LeapUnsubscribeEvents(LEAP_CONNECTION c, LEAP_DEVICE d) {
  if (c == nullptr || d == nullptr) return eLeapRS_InvalidArgument;
  std::lock_guard lock(state().mutex);
  ++state().stats.unsubscribed;
  state().subscribed.erase(d->id);
  return eLeapRS_Success;
}

int64_t LeapGetNow(void) {
  std::int64_t offset = 0;
  {
    std::lock_guard lock(state().mutex);
    offset = state().clock_offset_us;
  }
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch())
             .count() +
         offset;
}

}  // extern "C"
