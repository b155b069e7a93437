#pragma once
// What the LeapC backend tests share: waiting for the poll thread, a four-serial layout, and a
// consumer that keeps every frame and event the hub hands on.
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "devices/device_hub.h"
#include "devices/frame_consumer.h"
#include "devices/leapc/leapc_source.h"

namespace lmc::devices {

inline bool wait_for(const std::function<bool()>& done, int timeout_ms = 3000) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

// The backend's options for tests: the service's answers are judged after 50 ms instead of
// seconds (the double answers within a few polls), and a silent service is asked about after 100 ms.
inline LeapcOptions test_options() {
  LeapcOptions o;
  o.warning_grace_ms = 50;
  o.service_check_ms = 100;
  return o;
}

// Slots LMC1…LMCn bound to the serials LP11111, LP22222, … (n ≤ 8).
inline Layout layout_with_serials(int n = 4) {
  Layout l;
  l.name = "rig";
  for (int i = 0; i < n; ++i) {
    LayoutDevice d;
    d.slot = "LMC" + std::to_string(i + 1);
    d.serial = "LP" + std::string(5, static_cast<char>('1' + i));
    l.devices.push_back(d);
  }
  return l;
}

struct Recorded : FrameConsumer {
  std::mutex m;
  std::vector<HandFrame> frames;
  bool offer(const HandFrame& f, std::int64_t, bool) override {
    std::lock_guard lock(m);
    frames.push_back(f);
    return true;
  }
  std::vector<DeviceEvent> events;
  std::vector<int> other_side;  // device id of every frame marked as the other side's only hand
  void device_event(const DeviceEvent& e, int, const std::string&) override {
    std::lock_guard lock(m);
    events.push_back(e);
  }
  void other_side_hand(int device_id, std::int64_t) override {
    std::lock_guard lock(m);
    other_side.push_back(device_id);
  }
  size_t size() {
    std::lock_guard lock(m);
    return frames.size();
  }
};

// A hub on the four-serial layout with one LeapC source, its frames and events kept, started.
struct LeapcRig {
  explicit LeapcRig(LeapcOptions options = test_options()) : hub(layout_with_serials()) {
    hub.set_consumer(&rec);
    hub.add_source(std::make_unique<LeapcSource>(std::move(options)));
    hub.start();
  }
  Recorded rec;  // before the hub: the hub hands it frames until it stops
  DeviceHub hub;
};

}  // namespace lmc::devices
