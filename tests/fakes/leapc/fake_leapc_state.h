#pragma once
// The LeapC test double's state, shared by its scripting side (fake_leapc.cpp) and the LeapC
// functions it exports (fake_leapc_api.cpp). Internal to the double.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "fake_leapc.h"

struct lmc::devices::leapc::OpaqueConnection {
  bool open = false;
  bool closed = false;
};
struct lmc::devices::leapc::OpaqueDevice {
  std::uint32_t id = 0;
  std::string serial;
};

namespace fake_leapc {

struct Queued {
  std::uint32_t type = leapc::event::kNone;
  std::uint32_t device_id = 0;  // message device_id (0 = system-wide)
  leapc::DeviceEvent device{};
  leapc::DeviceFailureEvent failure{};
  leapc::DeviceStatusChangeEvent status{};
  leapc::DroppedFrameEvent dropped{};
  leapc::ConnectionEvent connection{};
  leapc::PolicyEvent policy{};
  leapc::TrackingModeEvent mode{};
  leapc::TrackingEvent tracking{};
  leapc::LogEvent log{};
  std::string log_text;
  std::vector<leapc::Hand> hands;
  const void* payload();  // the event the message points at
};

struct Failing {
  int times = 0;
  leapc::Result rs = leapc::kSuccess;
};

struct PluggedDevice {
  std::string serial;
  std::uint32_t pid = kPidPeripheral;
  std::uint32_t mode = leapc::kModeDesktop;
  std::uint64_t policy = 0;  // the policies in force
};

struct ModeChange {
  int polls_left = 0;
  std::uint32_t id = 0;
  std::uint32_t mode = 0;
};

struct State {
  std::mutex mutex;
  std::condition_variable cv;
  std::deque<std::unique_ptr<Queued>> queue;
  std::unique_ptr<Queued> current;  // the message the client holds until its next poll
  std::map<std::uint32_t, PluggedDevice> plugged;
  std::set<std::uint32_t> subscribed;
  std::map<std::uint32_t, leapc::Device> opened;  // the client's open handles by device id
  std::map<std::uint32_t, leapc::Result> policy_ex_result;
  std::map<std::uint32_t, std::uint64_t> refused_policy;
  std::map<std::uint32_t, std::uint32_t> held_mode;
  std::map<std::uint32_t, int> requested_mode;
  std::map<std::uint32_t, Failing> failing_open, failing_subscribe, failing_serial;
  std::map<std::uint32_t, std::int64_t> tracking_frame_id;
  std::vector<ModeChange> mode_changes;  // requests not in effect yet
  int mode_delay_polls = 3;
  int not_connected_polls = 0;
  bool silent = false;
  bool block = false;
  int block_max_ms = 1500;
  int overrun_every = 7;
  int overrun_ms = 3;
  long polls = 0;
  std::int64_t clock_offset_us = 0;
  std::int64_t clock_epoch_us = 0;
  int slow_calls = 0;
  std::int64_t slow_delay_us = 0;
  leapc::Version version{5, 6, 1};
  Stats stats;
  std::atomic<int> polling{0};
};

State& state();
void push_locked(std::unique_ptr<Queued> q);
void push(std::unique_ptr<Queued> q);
void push_mode_locked(std::uint32_t id, std::uint32_t mode);
void push_policy_locked(std::uint32_t id, std::uint64_t flags);
// Queues the Device, DeviceStatusChange and Policy events of a device that appears.
void announce_locked(std::uint32_t id);
// One injected failure used up, or kSuccess.
leapc::Result take_failure(std::map<std::uint32_t, Failing>& failing, std::uint32_t id);
std::int64_t steady_us();
void reset_locked(State& s);

}  // namespace fake_leapc
