#include "devices/leapc/leapc_source.h"

#include <LeapC.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <vector>

#include "core/common/error.h"
#include "devices/host_clock.h"

namespace lmc::devices {
namespace {

Vec3 to_vec(const LEAP_VECTOR& v) { return {v.x, v.y, v.z}; }

HandType to_hand_type(eLeapHandType t) { return t == eLeapHandType_Left ? HandType::kLeft : HandType::kRight; }

// The study's 28 points + 2 vectors (docs/algorithms/hand-points.md, devices/leapc/README.md).
void copy_hand(const LEAP_HAND& h, HandFrame& f) {
  f.point(kPalm) = to_vec(h.palm.position);
  f.point(kPalmNormal) = to_vec(h.palm.normal);
  f.point(kPalmDirection) = to_vec(h.palm.direction);
  f.point(kElbow) = to_vec(h.arm.prev_joint);
  f.point(kWrist) = to_vec(h.arm.next_joint);
  for (int d = 0; d < kNumDigits; ++d) {
    const LEAP_DIGIT& digit = h.digits[d];
    f.point(digit_point(d, 0)) = to_vec(digit.bones[0].prev_joint);
    for (int b = 0; b < 4; ++b) f.point(digit_point(d, b + 1)) = to_vec(digit.bones[b].next_joint);
  }
}

// eLeapDevicePID_LMC2 appeared in LeapC.h with SDK 5.11.0 (an enum value, so it cannot be tested
// with #ifdef): compare with its documented value so older 5.x SDKs still build.
constexpr std::uint32_t kPidLeapMotionController2 = 0x1206;

struct OpenDevice {
  LEAP_DEVICE handle = nullptr;
  std::string serial;
};

}  // namespace

std::string leapc_result_name(std::uint32_t rs) {
  switch (rs) {
    case eLeapRS_Success: return "eLeapRS_Success";
    case eLeapRS_UnknownError: return "eLeapRS_UnknownError";
    case eLeapRS_InvalidArgument: return "eLeapRS_InvalidArgument";
    case eLeapRS_InsufficientResources: return "eLeapRS_InsufficientResources";
    case eLeapRS_InsufficientBuffer: return "eLeapRS_InsufficientBuffer";
    case eLeapRS_Timeout: return "eLeapRS_Timeout";
    case eLeapRS_NotConnected: return "eLeapRS_NotConnected";
    case eLeapRS_HandshakeIncomplete: return "eLeapRS_HandshakeIncomplete";
    case eLeapRS_UnexpectedClosed: return "eLeapRS_UnexpectedClosed";
    case eLeapRS_ConcurrentPoll: return "eLeapRS_ConcurrentPoll";
    case eLeapRS_NotAvailable: return "eLeapRS_NotAvailable";
    case eLeapRS_NotStreaming: return "eLeapRS_NotStreaming";
    case eLeapRS_CannotOpenDevice: return "eLeapRS_CannotOpenDevice";
    default: break;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "eLeapRS 0x%08X", rs);
  return buf;
}

std::string leapc_status_text(std::uint32_t s) {
  switch (s) {
    case eLeapDeviceStatus_UnknownFailure: return "unknown failure";
    case eLeapDeviceStatus_BadCalibration: return "bad calibration";
    case eLeapDeviceStatus_BadFirmware: return "bad firmware";
    case eLeapDeviceStatus_BadTransport: return "bad transport (USB link: use its own port or a powered hub)";
    case eLeapDeviceStatus_BadControl: return "bad control";
    default: break;
  }
  std::string out;
  if (s & eLeapDeviceStatus_Streaming) out += "streaming ";
  if (s & eLeapDeviceStatus_Paused) out += "paused ";
  if (s & eLeapDeviceStatus_Robust) out += "robust mode ";
  if (s & eLeapDeviceStatus_Smudged) out += "smudged ";
  if (s & eLeapDeviceStatus_LowResource) out += "low resource ";
  if (!out.empty()) out.pop_back();
  return out.empty() ? "idle" : out;
}

struct LeapcSource::Impl {
  LEAP_CONNECTION connection = nullptr;
  std::map<std::uint32_t, OpenDevice> devices;  // by LEAP_DEVICE_REF.id

  ~Impl() { close(); }

  void close() {
    for (auto& [id, d] : devices) {
      if (connection != nullptr) LeapUnsubscribeEvents(connection, d.handle);
      LeapCloseDevice(d.handle);
    }
    devices.clear();
    if (connection != nullptr) {
      LeapCloseConnection(connection);
      LeapDestroyConnection(connection);
      connection = nullptr;
    }
  }
};

LeapcSource::LeapcSource(LeapcOptions options) : options_(options), impl_(std::make_unique<Impl>()) {}

LeapcSource::~LeapcSource() { stop(); }

void LeapcSource::start(FrameSink& sink) {
  if (thread_.joinable()) return;
  LEAP_CONNECTION_CONFIG config{};
  config.size = sizeof config;
  config.flags = eLeapConnectionConfig_MultiDeviceAware;
  config.server_namespace = nullptr;
  LEAP_CONNECTION connection = nullptr;
  if (const eLeapRS rs = LeapCreateConnection(&config, &connection); rs != eLeapRS_Success)
    throw Error("LeapC: cannot create a connection (" + leapc_result_name(rs) + ")");
  if (const eLeapRS rs = LeapOpenConnection(connection); rs != eLeapRS_Success) {
    LeapDestroyConnection(connection);
    throw Error("LeapC: cannot open the connection (" + leapc_result_name(rs) + ")");
  }
  impl_->connection = connection;
  // Policies are set per device once each is opened (LeapSetPolicyFlagsEx in run()): on a
  // multi-device-aware connection LeapSetPolicyFlags reaches only the primary device.
  stop_ = false;
  thread_ = std::thread([this, &sink] { run(sink); });
}

void LeapcSource::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  impl_->close();
}

void LeapcSource::run(FrameSink& sink) {
  Impl& im = *impl_;
  auto notice = [&](DeviceEventKind kind, const std::string& serial, std::string message, std::int64_t count = 0) {
    DeviceEvent e;
    e.kind = kind;
    e.info.serial = serial;
    e.info.backend = "leapc";
    e.message = std::move(message);
    e.count = count;
    e.host_time_ns = host_now_ns();
    sink.on_device_event(e);
  };
  auto serial_of = [&](std::uint32_t id) -> const std::string* {
    auto it = im.devices.find(id);
    return it == im.devices.end() ? nullptr : &it->second.serial;
  };
  int consecutive_errors = 0;
  while (!stop_) {
    LEAP_CONNECTION_MESSAGE msg;
    const eLeapRS rs = LeapPollConnection(im.connection, options_.poll_timeout_ms, &msg);
    if (rs == eLeapRS_Timeout) continue;
    if (rs != eLeapRS_Success) {
      // The service may be restarting; report once in a while, back off, keep polling.
      if (consecutive_errors++ % 50 == 0) notice(DeviceEventKind::kNotice, "", "LeapC poll failed: " + leapc_result_name(rs));
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    consecutive_errors = 0;
    const std::int64_t received_ns = host_now_ns();
    switch (msg.type) {
      case eLeapEventType_Connection:
        if (msg.connection_event != nullptr && msg.connection_event->flags != 0) {
          std::string what;
          if (msg.connection_event->flags & eLeapServiceState_LowFpsDetected) what += " low frame rate detected;";
          if (msg.connection_event->flags & eLeapServiceState_PoorPerformancePause) what += " paused for poor performance;";
          if (msg.connection_event->flags & eLeapServiceState_TrackingErrorUnknown) what += " tracking error;";
          notice(DeviceEventKind::kNotice, "", "Ultraleap service:" + what);
        }
        break;
      case eLeapEventType_ConnectionLost: {
        // Every device is gone until the service is back; it re-sends Device events then.
        for (auto& [id, d] : im.devices) {
          notice(DeviceEventKind::kLost, d.serial, "connection to the Ultraleap service lost");
          LeapCloseDevice(d.handle);
        }
        im.devices.clear();
        break;
      }
      case eLeapEventType_Device: {
        const LEAP_DEVICE_REF ref = msg.device_event->device;
        if (im.devices.count(ref.id) != 0) break;  // already open (duplicate announcement)
        LEAP_DEVICE handle = nullptr;
        if (const eLeapRS ors = LeapOpenDevice(ref, &handle); ors != eLeapRS_Success) {
          notice(DeviceEventKind::kNotice, "", "LeapC: cannot open device " + std::to_string(ref.id) + " (" + leapc_result_name(ors) + ")");
          break;
        }
        LEAP_DEVICE_INFO info{};
        info.size = sizeof info;
        info.serial = nullptr;
        LeapGetDeviceInfo(handle, &info);  // learns serial_length
        std::vector<char> serial(info.serial_length + 1, '\0');
        info.serial = serial.data();
        info.serial_length = static_cast<std::uint32_t>(serial.size());
        std::string serial_text;
        if (LeapGetDeviceInfo(handle, &info) == eLeapRS_Success) serial_text = serial.data();
        // Never key on an index: a device without a readable serial gets one from its id.
        if (serial_text.empty()) serial_text = "leapc-id-" + std::to_string(ref.id);
        if (const eLeapRS srs = LeapSubscribeEvents(im.connection, handle); srs != eLeapRS_Success) {
          notice(DeviceEventKind::kFailure, serial_text, "cannot subscribe to its events (" + leapc_result_name(srs) + "); service ≥ 5.4 needed");
        }
        // Per device: keep its frames coming while another window has focus (service ≥ 5.4).
        const eLeapRS prs = options_.background_frames
                                ? LeapSetPolicyFlagsEx(im.connection, handle, eLeapPolicyFlag_BackgroundFrames, 0)
                                : eLeapRS_Success;
        im.devices[ref.id] = {handle, serial_text};
        DeviceEvent e;
        e.kind = DeviceEventKind::kAppeared;
        e.info = {serial_text, "leapc",
                  static_cast<std::uint32_t>(info.pid) == kPidLeapMotionController2 ? "Leap Motion Controller 2"
                                                                                   : "Leap Motion Controller"};
        e.host_time_ns = received_ns;
        sink.on_device_event(e);
        if (prs != eLeapRS_Success)
          notice(DeviceEventKind::kNotice, serial_text,
                 "cannot set the background-frames policy (" + leapc_result_name(prs) +
                     "); it may stop streaming while another window has focus");
        break;
      }
      case eLeapEventType_DeviceLost: {
        const std::uint32_t id = msg.device_event->device.id;
        auto it = im.devices.find(id);
        if (it == im.devices.end()) break;
        const std::string serial = it->second.serial;
        LeapUnsubscribeEvents(im.connection, it->second.handle);
        LeapCloseDevice(it->second.handle);
        im.devices.erase(it);
        notice(DeviceEventKind::kLost, serial, "device lost");
        break;
      }
      case eLeapEventType_DeviceFailure: {
        // The event names its device by handle (hDevice, "may be NULL"); else the message's id.
        const std::string* serial = nullptr;
        if (msg.device_failure_event->hDevice != nullptr)
          for (const auto& [id, d] : im.devices)
            if (d.handle == msg.device_failure_event->hDevice) serial = &d.serial;
        if (serial == nullptr) serial = serial_of(msg.device_id);
        notice(DeviceEventKind::kFailure, serial ? *serial : "",
               (serial ? "" : "a device failed: ") + leapc_status_text(msg.device_failure_event->status));
        break;
      }
      case eLeapEventType_DeviceStatusChange: {
        const auto* ev = msg.device_status_change_event;
        const std::string* serial = serial_of(ev->device.id != 0 ? ev->device.id : msg.device_id);
        const bool failure = (ev->status & 0xE8010000u) == 0xE8010000u;
        notice(failure ? DeviceEventKind::kFailure : DeviceEventKind::kNotice, serial ? *serial : "",
               "status " + leapc_status_text(ev->last_status) + " → " + leapc_status_text(ev->status));
        break;
      }
      case eLeapEventType_DroppedFrame: {
        if (const std::string* serial = serial_of(msg.device_id))
          notice(DeviceEventKind::kDroppedFrames, *serial, "service dropped a frame", 1);
        break;
      }
      case eLeapEventType_Tracking: {
        const std::string* serial = serial_of(msg.device_id);
        if (serial == nullptr) break;  // not one of ours (or a system-wide message)
        const LEAP_TRACKING_EVENT& t = *msg.tracking_event;
        SourceFrame f;
        f.serial = *serial;
        f.host_receive_ns = received_ns;
        f.frame.frame_id = t.tracking_frame_id;
        f.frame.timestamp_us = t.info.timestamp;
        f.frame.frame_rate_hz = t.framerate;
        f.frame.points.fill(Vec3::Zero());
        for (std::uint32_t i = 0; i < t.nHands; ++i) {
          const LEAP_HAND& h = t.pHands[i];
          if (to_hand_type(h.type) != options_.wanted_hand) continue;
          copy_hand(h, f.frame);
          f.frame.hand_present = true;
          f.hand_type = to_hand_type(h.type);
          f.confidence = h.confidence;
          break;
        }
        sink.on_frame(f);
        break;
      }
      default:
        break;
    }
  }
}

std::vector<DeviceInfo> leapc_list_devices(std::uint32_t wait_ms) {
  struct Collect final : FrameSink {
    std::mutex m;
    std::vector<DeviceInfo> devices;
    void on_device_event(const DeviceEvent& e) override {
      std::lock_guard lock(m);
      if (e.kind == DeviceEventKind::kAppeared) devices.push_back(e.info);
    }
    void on_frame(const SourceFrame&) override {}
  } collect;
  LeapcSource source;
  source.start(collect);
  std::this_thread::sleep_for(std::chrono::milliseconds(wait_ms));
  source.stop();
  std::lock_guard lock(collect.m);
  return collect.devices;
}

}  // namespace lmc::devices
