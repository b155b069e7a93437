// The LeapC test double's scripting side (fake_leapc.h). Written from the public API reference.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "fake_leapc_state.h"

namespace fake_leapc {
namespace {

leapc::Vector vec(float x, float y, float z) {
  return {x, y, z};
}

std::unique_ptr<Queued> message(std::uint32_t type, std::uint32_t device_id = 0) {
  auto q = std::make_unique<Queued>();
  q->type = type;
  q->device_id = device_id;
  return q;
}

// "6.1.0" → {6, 1, 0}; the default when unset or unreadable.
leapc::Version version_from_env() {
  leapc::Version v{5, 6, 1};
  if (const char* text = std::getenv("LMC_FAKE_LEAPC_VERSION"); text != nullptr)
    if (std::sscanf(text, "%d.%d.%d", &v.major, &v.minor, &v.patch) != 3) v = {5, 6, 1};
  return v;
}

}  // namespace

State& state() {
  static State s;
  static const bool initialised = [] {
    std::lock_guard lock(s.mutex);
    reset_locked(s);
    return true;
  }();
  (void)initialised;
  return s;
}

std::int64_t steady_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

const void* Queued::payload() {
  switch (type) {
    case leapc::event::kDevice:
    case leapc::event::kDeviceLost:
      return &device;
    case leapc::event::kDeviceFailure:
      return &failure;
    case leapc::event::kDeviceStatusChange:
      return &status;
    case leapc::event::kDroppedFrame:
      return &dropped;
    case leapc::event::kConnection:
    case leapc::event::kConnectionLost:
      return &connection;
    case leapc::event::kPolicy:
      return &policy;
    case leapc::event::kTrackingMode:
      return &mode;
    case leapc::event::kLogEvent:
      log.message = log_text.c_str();
      return &log;
    case leapc::event::kTracking:
      tracking.nHands = static_cast<std::uint32_t>(hands.size());
      tracking.pHands = hands.empty() ? nullptr : hands.data();
      return &tracking;
    default:
      return nullptr;
  }
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

void push_mode_locked(std::uint32_t id, std::uint32_t mode) {
  auto q = message(leapc::event::kTrackingMode, id);
  q->mode.current_tracking_mode = mode;
  push_locked(std::move(q));
}

void push_policy_locked(std::uint32_t id, std::uint64_t flags) {
  auto q = message(leapc::event::kPolicy, id);
  q->policy.current_policy = static_cast<std::uint32_t>(flags);
  push_locked(std::move(q));
}

void announce_locked(std::uint32_t id) {
  auto q = message(leapc::event::kDevice);
  q->device.device.id = id;
  q->device.device.handle = reinterpret_cast<void*>(static_cast<std::uintptr_t>(id) * 16);
  q->device.status = leapc::kStatusStreaming;
  push_locked(std::move(q));
  auto st = message(leapc::event::kDeviceStatusChange, id);
  st->status.device.id = id;
  st->status.last_status = 0;
  st->status.status = leapc::kStatusStreaming;
  push_locked(std::move(st));
  // The service says the device's policies as it connects: none that this client asked for yet.
  push_policy_locked(id, state().plugged[id].policy);
}

leapc::Result take_failure(std::map<std::uint32_t, Failing>& failing, std::uint32_t id) {
  auto it = failing.find(id);
  if (it == failing.end() || it->second.times <= 0) return leapc::kSuccess;
  --it->second.times;
  return it->second.rs;
}

void reset_locked(State& s) {
  s.queue.clear();
  s.current.reset();
  s.plugged.clear();
  s.subscribed.clear();
  s.opened.clear();
  s.policy_ex_result.clear();
  s.refused_policy.clear();
  s.held_mode.clear();
  s.requested_mode.clear();
  s.failing_open.clear();
  s.failing_subscribe.clear();
  s.failing_serial.clear();
  s.tracking_frame_id.clear();
  s.mode_changes.clear();
  s.mode_delay_polls = 3;
  s.not_connected_polls = 0;
  s.silent = false;
  s.block = false;
  s.overrun_every = 7;
  s.overrun_ms = 3;
  s.polls = 0;
  s.clock_offset_us = 0;
  s.clock_epoch_us = steady_us();
  s.slow_calls = 0;
  s.version = version_from_env();
  s.stats = {};
}

void reset() {
  State& s = state();
  std::lock_guard lock(s.mutex);
  reset_locked(s);
}

void plug(std::uint32_t id, const std::string& serial, std::uint32_t pid, std::uint32_t mode) {
  {
    std::lock_guard lock(state().mutex);
    state().plugged[id] = {serial, pid, mode, 0};
    announce_locked(id);
  }
  state().cv.notify_all();
}

void announce(std::uint32_t id) {
  auto q = message(leapc::event::kDevice);
  q->device.device.id = id;
  q->device.status = leapc::kStatusStreaming;
  push(std::move(q));
}

void unplug(std::uint32_t id) {
  auto q = message(leapc::event::kDeviceLost);
  q->device.device.id = id;
  push(std::move(q));
}

void device_failure(std::uint32_t id, std::uint32_t status, bool with_handle, bool with_message_device_id) {
  auto q = message(leapc::event::kDeviceFailure, with_message_device_id ? id : 0);
  q->failure.status = status;
  q->failure.hDevice = nullptr;  // "may be NULL" per the reference
  if (with_handle) {
    std::lock_guard lock(state().mutex);
    auto it = state().opened.find(id);
    if (it != state().opened.end()) q->failure.hDevice = it->second;
  }
  push(std::move(q));
}

void fail_policy_ex(std::uint32_t id, leapc::Result rs) {
  std::lock_guard lock(state().mutex);
  if (rs == leapc::kSuccess)
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
  auto it = state().plugged.find(id);
  return it == state().plugged.end() ? 0 : it->second.policy;
}

void hold_tracking_mode(std::uint32_t id, std::uint32_t mode) {
  std::lock_guard lock(state().mutex);
  state().held_mode[id] = mode;
}

void change_tracking_mode(std::uint32_t id, std::uint32_t mode) {
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

void set_mode_delay_polls(int polls) {
  std::lock_guard lock(state().mutex);
  state().mode_delay_polls = polls;
}

void fail_open(std::uint32_t id, int times, leapc::Result rs) {
  std::lock_guard lock(state().mutex);
  state().failing_open[id] = {times, rs};
}

void fail_subscribe(std::uint32_t id, int times, leapc::Result rs) {
  std::lock_guard lock(state().mutex);
  state().failing_subscribe[id] = {times, rs};
}

void fail_serial(std::uint32_t id, int times, leapc::Result rs) {
  std::lock_guard lock(state().mutex);
  state().failing_serial[id] = {times, rs};
}

void not_connected_polls(int polls) {
  std::lock_guard lock(state().mutex);
  state().not_connected_polls = polls;
}

void silent_service(bool silent) {
  std::lock_guard lock(state().mutex);
  state().silent = silent;
  if (silent) state().queue.clear();
}

void block_polls(bool block, int max_ms) {
  {
    std::lock_guard lock(state().mutex);
    state().block = block;
    state().block_max_ms = max_ms;
  }
  state().cv.notify_all();
}

void set_poll_overrun(int every, int extra_ms) {
  std::lock_guard lock(state().mutex);
  state().overrun_every = every;
  state().overrun_ms = extra_ms;
}

void status_change(std::uint32_t id, std::uint32_t last_status, std::uint32_t status) {
  auto q = message(leapc::event::kDeviceStatusChange, id);
  q->status.device.id = id;
  q->status.last_status = last_status;
  q->status.status = status;
  push(std::move(q));
}

void dropped_frame(std::uint32_t id, std::int64_t frame_id) {
  auto q = message(leapc::event::kDroppedFrame, id);
  q->dropped.frame_id = frame_id;
  q->dropped.type = 1;  // tracking queue
  push(std::move(q));
}

void log_event(std::uint32_t severity, const std::string& text) {
  auto q = message(leapc::event::kLogEvent);
  q->log.severity = severity;
  q->log_text = text;
  push(std::move(q));
}

void connection_lost() {
  {
    std::lock_guard lock(state().mutex);
    for (const auto& [id, d] : state().plugged) {
      auto q = message(leapc::event::kDeviceLost);
      q->device.device.id = id;
      push_locked(std::move(q));
    }
    push_locked(message(leapc::event::kConnectionLost));
  }
  state().cv.notify_all();
}

std::vector<std::uint32_t> reconnect(std::uint32_t id_offset) {
  std::vector<std::uint32_t> ids;
  {
    std::lock_guard lock(state().mutex);
    State& s = state();
    push_locked(message(leapc::event::kConnection));
    std::map<std::uint32_t, PluggedDevice> renamed;
    for (auto& [id, d] : s.plugged) {
      renamed[id + id_offset] = d;
      renamed[id + id_offset].policy = 0;
      ids.push_back(id + id_offset);
    }
    s.plugged = renamed;
    s.subscribed.clear();
    for (const std::uint32_t id : ids) announce_locked(id);
  }
  state().cv.notify_all();
  return ids;
}

void connection_event(std::uint32_t flags) {
  auto q = message(leapc::event::kConnection);
  q->connection.flags = flags;
  push(std::move(q));
}

void track(std::uint32_t id, std::int64_t frame_id, std::int64_t timestamp_us, float framerate,
           const std::vector<leapc::Hand>& hands) {
  auto q = message(leapc::event::kTracking, id);
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

leapc::Hand make_hand(std::uint32_t type, float base) {
  leapc::Hand h;
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
  std::lock_guard lock(state().mutex);
  const State& s = state();
  const std::int64_t elapsed = steady_us() - s.clock_epoch_us;
  return s.clock_epoch_us + elapsed + elapsed / 20'000 + s.clock_offset_us;  // 50 ppm fast
}

void slow_get_now(int calls, std::int64_t delay_us) {
  std::lock_guard lock(state().mutex);
  state().slow_calls = calls;
  state().slow_delay_us = delay_us;
}

void set_version(int major, int minor, int patch) {
  std::lock_guard lock(state().mutex);
  state().version = {major, minor, patch};
}

Stats stats() {
  State& s = state();
  std::lock_guard lock(s.mutex);
  Stats out = s.stats;
  out.pending = static_cast<int>(s.queue.size());
  out.open_handles = static_cast<int>(s.opened.size());
  return out;
}

}  // namespace fake_leapc
