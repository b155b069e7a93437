// The LeapC functions the test double exports, under LeapC's own names and signatures
// (devices/leapc/leapc_abi.h), so the backend finds them with dlsym as it finds the real ones.
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <thread>

#include "fake_leapc_state.h"

using namespace fake_leapc;  // NOLINT: the double's own internals
using lmc::devices::leapc::Connection;
using lmc::devices::leapc::ConnectionConfig;
using lmc::devices::leapc::ConnectionInfo;
using lmc::devices::leapc::ConnectionMessage;
using lmc::devices::leapc::Device;
using lmc::devices::leapc::DeviceInfo;
using lmc::devices::leapc::DeviceRef;
using lmc::devices::leapc::Result;
using lmc::devices::leapc::Version;

// Exported, so the marker's text is in the library's bytes whatever the linker drops.
extern "C" const char* lmc_fake_leapc_marker() {
  return kMarker;
}

namespace {

// LMC_FAKE_LEAPC_DEVICES="3:LP11111,7:LP22222": devices plugged when the connection opens, so a
// test of the real `lmc` binary has controllers to list.
void plug_from_env() {
  const char* text = std::getenv("LMC_FAKE_LEAPC_DEVICES");
  if (text == nullptr) return;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto colon = item.find(':');
    if (colon == std::string::npos) continue;
    plug(static_cast<std::uint32_t>(std::strtoul(item.substr(0, colon).c_str(), nullptr, 10)), item.substr(colon + 1));
  }
}

// Mode requests whose delay is over take effect now (the lock is held).
void apply_due_mode_changes(State& s) {
  std::vector<ModeChange> still;
  for (ModeChange& c : s.mode_changes) {
    if (--c.polls_left > 0) {
      still.push_back(c);
      continue;
    }
    s.plugged[c.id].mode = c.mode;
    push_mode_locked(c.id, c.mode);
  }
  s.mode_changes = still;
}

// The next deliverable message, or null (tracking of unsubscribed devices is dropped).
std::unique_ptr<Queued> next_message(State& s) {
  while (!s.queue.empty()) {
    auto q = std::move(s.queue.front());
    s.queue.pop_front();
    if (q->type == lmc::devices::leapc::event::kTracking && s.subscribed.count(q->device_id) == 0) {
      ++s.stats.tracking_suppressed;
      continue;
    }
    if (q->type == lmc::devices::leapc::event::kTracking) ++s.stats.tracking_delivered;
    if (q->type == lmc::devices::leapc::event::kDeviceLost) s.subscribed.erase(q->device.device.id);
    return q;
  }
  return nullptr;
}

Result poll_locked(State& s, std::unique_lock<std::mutex>& lock, Connection c, std::uint32_t timeout,
                   ConnectionMessage* evt) {
  ++s.polls;
  apply_due_mode_changes(s);
  if (s.not_connected_polls > 0) {
    // No service yet: LeapC answers at once. Once the service is up, the first message is the
    // Connection event.
    if (--s.not_connected_polls == 0) {
      auto q = std::make_unique<Queued>();
      q->type = lmc::devices::leapc::event::kConnection;
      s.queue.push_front(std::move(q));
    }
    return lmc::devices::leapc::kNotConnected;
  }
  if (s.block) {
    s.cv.wait_for(lock, std::chrono::milliseconds(s.block_max_ms), [&] { return c->closed; });
    return c->closed ? lmc::devices::leapc::kNotConnected : lmc::devices::leapc::kTimeout;
  }
  const bool overrun = s.overrun_every > 0 && s.polls % s.overrun_every == 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout) +
                        std::chrono::milliseconds(overrun ? s.overrun_ms : 0);
  for (;;) {
    if (c->closed) return lmc::devices::leapc::kNotConnected;
    if (!s.silent)
      if (auto q = next_message(s)) {
        evt->type = q->type;
        evt->device_id = q->device_id;
        evt->event = q->payload();
        s.current = std::move(q);
        return lmc::devices::leapc::kSuccess;
      }
    if (s.cv.wait_until(lock, deadline) == std::cv_status::timeout && (s.silent || s.queue.empty())) break;
  }
  return lmc::devices::leapc::kTimeout;
}

}  // namespace

extern "C" {

Result LeapCreateConnection(const ConnectionConfig* config, Connection* out) {
  if (out == nullptr) return lmc::devices::leapc::kInvalidArgument;
  std::lock_guard lock(state().mutex);
  ++state().stats.connections_created;
  if (config != nullptr && (config->flags & lmc::devices::leapc::kConnectionConfigMultiDeviceAware) != 0)
    ++state().stats.multi_device_aware;
  *out = new lmc::devices::leapc::OpaqueConnection();
  return lmc::devices::leapc::kSuccess;
}

Result LeapOpenConnection(Connection c) {
  if (c == nullptr) return lmc::devices::leapc::kInvalidArgument;
  {
    std::lock_guard lock(state().mutex);
    c->open = true;
    ++state().stats.connections_opened;
    // The service greets every client that connects (when it is up).
    if (state().not_connected_polls == 0 && !state().silent) {
      auto q = std::make_unique<Queued>();
      q->type = lmc::devices::leapc::event::kConnection;
      push_locked(std::move(q));
    }
  }
  plug_from_env();
  return lmc::devices::leapc::kSuccess;
}

void LeapCloseConnection(Connection c) {
  if (c == nullptr) return;
  {
    std::lock_guard lock(state().mutex);
    c->open = false;
    c->closed = true;
    ++state().stats.connections_closed;
  }
  state().cv.notify_all();
}

void LeapDestroyConnection(Connection c) {
  {
    std::lock_guard lock(state().mutex);
    state().current.reset();
  }
  delete c;
}

Result LeapGetConnectionInfo(Connection c, ConnectionInfo* info) {
  if (c == nullptr || info == nullptr) return lmc::devices::leapc::kInvalidArgument;
  std::lock_guard lock(state().mutex);
  info->status = state().silent                                ? lmc::devices::leapc::kConnectionNotRunning
                 : c->open && state().not_connected_polls == 0 ? lmc::devices::leapc::kConnectionConnected
                                                               : lmc::devices::leapc::kConnectionNotConnected;
  return lmc::devices::leapc::kSuccess;
}

Result LeapGetVersion(Connection c, std::uint32_t part, Version* v) {
  if (c == nullptr || v == nullptr) return lmc::devices::leapc::kInvalidArgument;
  std::lock_guard lock(state().mutex);
  if (part == lmc::devices::leapc::kVersionServerLibrary && !c->open) return lmc::devices::leapc::kNotConnected;
  *v = state().version;
  return lmc::devices::leapc::kSuccess;
}

Result LeapSetPolicyFlagsEx(Connection c, Device d, std::uint64_t set, std::uint64_t clear) {
  if (c == nullptr || d == nullptr) return lmc::devices::leapc::kInvalidArgument;
  {
    std::lock_guard lock(state().mutex);
    State& s = state();
    ++s.stats.policy_ex_calls;
    if (auto it = s.policy_ex_result.find(d->id); it != s.policy_ex_result.end()) return it->second;
    auto& flags = s.plugged[d->id].policy;
    flags = (flags | set) & ~clear;
    if (auto it = s.refused_policy.find(d->id); it != s.refused_policy.end()) flags &= ~it->second;
    // Accepted; what the service made of it arrives later, as a Policy event.
    push_policy_locked(d->id, flags);
  }
  state().cv.notify_all();
  return lmc::devices::leapc::kSuccess;
}

Result LeapSetTrackingModeEx(Connection c, Device d, std::uint32_t mode) {
  if (c == nullptr || d == nullptr) return lmc::devices::leapc::kInvalidArgument;
  {
    std::lock_guard lock(state().mutex);
    State& s = state();
    ++s.stats.tracking_mode_calls;
    s.requested_mode[d->id] = static_cast<int>(mode);
    auto held = s.held_mode.find(d->id);
    const std::uint32_t next = held != s.held_mode.end() ? held->second : mode;
    if (s.mode_delay_polls <= 0) {
      s.plugged[d->id].mode = next;
      push_mode_locked(d->id, next);
    } else {
      s.mode_changes.push_back({s.mode_delay_polls, d->id, next});
    }
  }
  state().cv.notify_all();
  return lmc::devices::leapc::kSuccess;
}

Result LeapGetTrackingModeEx(Connection c, Device d) {
  if (c == nullptr || d == nullptr) return lmc::devices::leapc::kInvalidArgument;
  {
    std::lock_guard lock(state().mutex);
    ++state().stats.tracking_mode_queries;
    push_mode_locked(d->id, state().plugged[d->id].mode);
  }
  state().cv.notify_all();
  return lmc::devices::leapc::kSuccess;
}

Result LeapPollConnection(Connection c, std::uint32_t timeout, ConnectionMessage* evt) {
  State& s = state();
  if (c == nullptr || evt == nullptr) return lmc::devices::leapc::kInvalidArgument;
  if (s.polling.fetch_add(1) != 0) {
    s.polling.fetch_sub(1);
    std::lock_guard lock(s.mutex);
    ++s.stats.concurrent_polls;
    return lmc::devices::leapc::kConcurrentPoll;
  }
  std::unique_lock lock(s.mutex);
  s.current.reset();  // the previous message's pointers die here, as documented
  std::memset(evt, 0, sizeof *evt);
  evt->size = sizeof *evt;
  const Result rs = poll_locked(s, lock, c, timeout, evt);
  s.polling.fetch_sub(1);
  return rs;
}

Result LeapOpenDevice(DeviceRef ref, Device* out) {
  if (out == nullptr) return lmc::devices::leapc::kInvalidArgument;
  std::lock_guard lock(state().mutex);
  State& s = state();
  ++s.stats.open_attempts;
  auto it = s.plugged.find(ref.id);
  if (it == s.plugged.end()) return lmc::devices::leapc::kCannotOpenDevice;
  if (const Result rs = take_failure(s.failing_open, ref.id); rs != lmc::devices::leapc::kSuccess) return rs;
  ++s.stats.devices_opened;
  *out = new lmc::devices::leapc::OpaqueDevice{ref.id, it->second.serial};
  s.opened[ref.id] = *out;
  return lmc::devices::leapc::kSuccess;
}

void LeapCloseDevice(Device d) {
  if (d == nullptr) return;
  {
    std::lock_guard lock(state().mutex);
    ++state().stats.devices_closed;
    if (auto it = state().opened.find(d->id); it != state().opened.end() && it->second == d) state().opened.erase(it);
    state().subscribed.erase(d->id);
    // "Valid until the connection or the device is closed": the message in hand dies here.
    state().current.reset();
  }
  delete d;
}

Result LeapGetDeviceInfo(Device d, DeviceInfo* info) {
  if (d == nullptr || info == nullptr || info->size != sizeof(DeviceInfo)) return lmc::devices::leapc::kInvalidArgument;
  const auto needed = static_cast<std::uint32_t>(d->serial.size() + 1);
  info->status = lmc::devices::leapc::kStatusStreaming;
  {
    std::lock_guard lock(state().mutex);
    auto it = state().plugged.find(d->id);
    info->pid = it == state().plugged.end() ? 0 : it->second.pid;
    if (info->serial != nullptr)
      if (const Result rs = take_failure(state().failing_serial, d->id); rs != lmc::devices::leapc::kSuccess) return rs;
  }
  info->baseline = 40000;
  info->h_fov = 2.618F;
  info->v_fov = 2.094F;
  info->range = 600000;
  // As documented: with serial == NULL (or too short a buffer) the call reports the length.
  if (info->serial == nullptr || info->serial_length < needed) {
    info->serial_length = needed;
    return info->serial == nullptr ? lmc::devices::leapc::kSuccess : lmc::devices::leapc::kInsufficientBuffer;
  }
  std::memcpy(info->serial, d->serial.c_str(), needed);
  info->serial_length = needed;
  return lmc::devices::leapc::kSuccess;
}

Result LeapSubscribeEvents(Connection c, Device d) {
  if (c == nullptr || d == nullptr) return lmc::devices::leapc::kInvalidArgument;
  std::lock_guard lock(state().mutex);
  State& s = state();
  ++s.stats.subscribe_attempts;
  if (const Result rs = take_failure(s.failing_subscribe, d->id); rs != lmc::devices::leapc::kSuccess) return rs;
  ++s.stats.subscribed;
  s.subscribed.insert(d->id);
  return lmc::devices::leapc::kSuccess;
}

Result LeapUnsubscribeEvents(Connection c, Device d) {
  if (c == nullptr || d == nullptr) return lmc::devices::leapc::kInvalidArgument;
  std::lock_guard lock(state().mutex);
  ++state().stats.unsubscribed;
  state().subscribed.erase(d->id);
  return lmc::devices::leapc::kSuccess;
}

std::int64_t LeapGetNow(void) {
  std::int64_t delay = 0;
  {
    std::lock_guard lock(state().mutex);
    if (state().slow_calls > 0) {
      --state().slow_calls;
      delay = state().slow_delay_us;
    }
  }
  // A slow call: the thread was switched out before the clock was read.
  if (delay > 0) std::this_thread::sleep_for(std::chrono::microseconds(delay));
  return now_us();
}

}  // extern "C"
