#pragma once
// One interface for every source of hand frames (simulated rig, replay, LeapC): a source runs
// its own thread(s) and reports to a FrameSink (the hub) devices appearing and disappearing, keyed
// by serial number, and one SourceFrame per tracking event of each device. Sources never decide
// layout slots; the hub maps serial → slot (devices/leapc/README.md: identity by serial, never by index).
#include <cstdint>
#include <optional>
#include <string>

#include "core/hand/hand_frame.h"

namespace lmc::devices {

struct DeviceInfo {
  std::string serial;
  std::string backend;  // "sim", "replay", "leapc"
  std::string model;    // "Leap Motion Controller", "simulated", ...
  // "desktop", "screen-top", "head-mounted" (devices/tracking_mode.h); empty until known.
  std::string tracking_mode;
  // The LeapC product id (LEAP_DEVICE_INFO::pid) of the hardware, or of the model a simulated
  // device stands in for; 0 when not known (replay).
  std::uint32_t product_id = 0;
};

// One tracking event of one device, copied out of the backend's buffers.
struct SourceFrame {
  std::string serial;
  // frame.device_id is the source's own device number; the hub rewrites it to the slot number.
  // Coordinates are in the device's own frame (docs/algorithms/frames.md).
  HandFrame frame;
  std::int64_t host_receive_ns = 0;  // host steady clock (or simulated host time), ns
  HandType hand_type = HandType::kUnknown;
  float confidence = -1.0F;  // < 0 when the backend does not know (LeapC documents it as unused)
  // The only hand in view was classified as the other side than the wanted one and was kept as
  // the subject's hand (hand_type says what the tracker called it).
  bool other_side_hand = false;
};

enum class DeviceEventKind {
  kAppeared,       // a device is streaming (or about to); `info` is filled
  kLost,           // unplugged / closed / service lost
  kFailure,        // device reported a failure status; it may keep streaming
  kDroppedFrames,  // the service says it dropped `count` frames of this device
  kNotice,         // anything the operator should read (low fps, bad transport, ...)
  kTrackingMode,   // the device's tracking mode is known or changed: info.tracking_mode; `message`
                   // says why it matters when it is not the mode that was asked for
};

struct DeviceEvent {
  DeviceEventKind kind = DeviceEventKind::kNotice;
  DeviceInfo info;  // info.serial always set when the event is about one device
  std::string message;
  std::int64_t host_time_ns = 0;
  std::int64_t count = 0;
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void on_device_event(const DeviceEvent& event) = 0;
  virtual void on_frame(const SourceFrame& frame) = 0;
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual std::string backend_name() const = 0;
  // Starts delivering to `sink` from the source's own thread(s); returns immediately.
  virtual void start(FrameSink& sink) = 0;
  // Stops and joins; no callback runs after stop() returns. Safe to call twice.
  virtual void stop() = 0;
  // True for hardware-paced sources (their threads must never block). A simulated source run
  // faster than real time returns false; the hub may then apply back-pressure instead of dropping.
  virtual bool realtime() const { return true; }
  // True when a finite source (replay, simulated trial) has delivered everything.
  virtual bool finished() const { return false; }
  // The device clock (the clock of frame timestamps, µs) at host instant `host_ns`, read from the
  // clock itself (LeapGetNow for LeapC): a frame's timestamp is its capture time, which precedes
  // its arrival by the delivery latency, so "latest timestamp + time since it arrived" runs late
  // by that latency. `host_ns` should be recent (a live clock is read now and carried to it on
  // the host clock). nullopt when the source has no clock to read (replay; simulated time run
  // faster than real time); any thread.
  virtual std::optional<std::int64_t> device_clock_us(std::int64_t /*host_ns*/) const { return std::nullopt; }
  // How far the latest device_clock_us may be off, µs: half the host interval the clock was read
  // in. nullopt when the source does not know (or has no clock). Read it right after the clock.
  virtual std::optional<std::int64_t> device_clock_uncertainty_us() const { return std::nullopt; }
};

}  // namespace lmc::devices
