#pragma once
// The device hub: runs frame sources, maps serial numbers to the layout's slots,
// keeps per-device statistics, hands the UI thread-safe snapshots and fans frames out to the
// recorder. Device threads only take a short lock to update counters and copy the latest frame;
// they never wait on the UI or on the disk (docs/architecture.md).
#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/hand/hand_frame.h"
#include "core/layout/layout.h"
#include "devices/frame_consumer.h"
#include "devices/frame_source.h"
#include "devices/frame_tap.h"
#include "devices/host_clock.h"

namespace lmc::devices {

struct DeviceStatus {
  std::string serial;
  std::string backend;
  std::string model;
  int slot_index = -1;  // index into the layout's devices, −1 when unassigned
  std::string slot;     // "LMC2", empty when unassigned
  bool connected = false;
  double rate_hz = 0.0;                     // frames received during the last second
  double latest_frame_age_ms = -1;          // −1 before the first frame
  std::int64_t latest_host_receive_ns = 0;  // host_now_ns() when the latest frame arrived (0 before)
  bool hand_present = false;
  HandType hand_type = HandType::kUnknown;
  std::int64_t frames_received = 0;
  std::int64_t frames_dropped = 0;           // frame-id gaps + drops the service reported
  std::int64_t frames_dropped_recorder = 0;  // the recorder's queue was full
  int disconnects = 0;
  std::optional<HandFrame> latest;  // latest frame in the device frame (device_id = slot number)
  // As the backend reports them: the tracking mode ("desktop", …; empty until known), the frames
  // whose only hand was classified as the other side and kept, and the device clock read at the
  // snapshot's host_time_ns (FrameSource::device_clock_us; nullopt when its source has none).
  std::string tracking_mode;
  std::int64_t frames_other_side_hand = 0;
  std::optional<std::int64_t> device_clock_us;
  std::optional<std::int64_t> device_clock_uncertainty_us;  // FrameSource::device_clock_uncertainty_us
  std::uint32_t product_id = 0;                             // as the backend reported it (0: not known)
  // Set when the connected controller is not the model its slot is laid out as
  // (slot_model_mismatch, core/layout/sensor_catalogue.h); empty otherwise.
  std::string model_warning;
};

struct HubSnapshot {
  std::vector<std::string> slots;     // the layout's slot names, in order
  std::vector<DeviceStatus> devices;  // every device seen, assigned ones first (slot order)
  std::vector<std::string> unassigned_serials;
  std::int64_t host_time_ns = 0;
};

struct HubOptions {
  // A serial not bound in the layout takes the first slot that has no serial and no device yet
  // (in order of appearance, as the study named LMC1…LMC4). Off: it is listed for assignment.
  bool auto_assign = true;
  HostClock clock = host_now_ns;
  // Simulated time run faster than real time (`lmc record --fast`): nothing is hardware-paced,
  // so the consumer may make producers wait instead of dropping frames.
  bool backpressure = false;
  size_t max_messages = 200;
};

class DeviceHub final : public FrameSink {
 public:
  explicit DeviceHub(Layout layout, HubOptions options = {});
  ~DeviceHub() override;
  DeviceHub(const DeviceHub&) = delete;
  DeviceHub& operator=(const DeviceHub&) = delete;

  void add_source(std::unique_ptr<FrameSource> source);
  void start();
  void stop();
  bool running() const;
  // False when the hub plays simulated time faster than real time (HubOptions::backpressure):
  // its frames' host times then do not follow the wall clock.
  bool realtime() const { return !options_.backpressure; }
  // True when every source is finite and finished.
  bool sources_finished() const;
  std::vector<std::string> backends() const;

  // The recorder (or nullptr). The consumer must outlive its registration.
  void set_consumer(FrameConsumer* consumer);
  // Display-only listeners (frame_tap.h), called after the consumer for every assigned frame.
  // A tap must outlive its registration; remove_tap() returns once no device thread is inside it.
  void add_tap(FrameTap* tap);
  void remove_tap(FrameTap* tap);

  // Binds a serial to a slot (the slot's previous device, if any, becomes unassigned). Returns
  // an empty string on success, else why not.
  std::string assign(const std::string& serial, const std::string& slot);
  void unassign(const std::string& serial);
  // Current serial → slot map (assigned devices only).
  std::vector<std::pair<std::string, std::string>> serial_to_slot() const;

  HubSnapshot snapshot() const;
  // Operator messages (device appeared/lost, failures, drops) since the last call.
  std::vector<std::string> take_messages();

  const Layout& layout() const { return layout_; }

  // FrameSink (device threads).
  void on_device_event(const DeviceEvent& event) override;
  void on_frame(const SourceFrame& frame) override;

 private:
  struct Device {
    DeviceStatus status;
    std::int64_t last_frame_id = -1;
    std::int64_t last_receive_ns = 0;
    std::array<std::int64_t, 512> recent_ns{};  // ring of receive times for the 1 s rate
    size_t recent_head = 0;
    size_t recent_count = 0;
    bool auto_assigned = false;  // slot given in order of appearance, not from the layout's serials
  };
  Device& device_for_locked(const std::string& serial);
  void try_auto_assign_locked(Device& d);
  // Sets d's model_warning from its product id and its slot's model, saying so when it is new.
  void check_model_locked(Device& d);
  void message_locked(std::string text);
  static std::string label(const DeviceStatus& s);

  Layout layout_;
  HubOptions options_;
  mutable std::mutex mutex_;
  std::mutex consumer_mutex_;   // held only around consumer calls, never with mutex_
  std::deque<Device> devices_;  // deque: stable addresses
  std::deque<std::string> messages_;
  FrameConsumer* consumer_ = nullptr;
  std::mutex tap_mutex_;  // held only around tap calls, never with mutex_ or consumer_mutex_
  std::vector<FrameTap*> taps_;
  std::vector<std::unique_ptr<FrameSource>> sources_;
  bool running_ = false;
};

}  // namespace lmc::devices
