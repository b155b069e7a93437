#include "devices/leapc/leapc_source.h"

#include <LeapC.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <set>
#include <utility>
#include <vector>

#include "core/common/error.h"
#include "devices/host_clock.h"
#include "devices/tracking_mode.h"

namespace lmc::devices {
namespace {

constexpr std::int64_t kDropReportIntervalNs = 1'000'000'000;  // dropped frames: one event per device and second

Vec3 to_vec(const LEAP_VECTOR& v) {
  return {v.x, v.y, v.z};
}

HandType to_hand_type(eLeapHandType t) {
  return t == eLeapHandType_Left ? HandType::kLeft : HandType::kRight;
}

// The study's 28 points + 2 vectors (docs/algorithms/hand-points.md).
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

// Product ids as LeapC.h numbers them. eLeapDevicePID_LMC2 appeared in LeapC.h with SDK 5.11.0
// and SIR170/3Di with 5.3.0 (enum values, so they cannot be tested with #ifdef): compared by
// value so the study's 5.6.1 and other older 5.x SDKs build.
constexpr std::uint32_t kPidLeapMotionController = 0x0003;
constexpr std::uint32_t kPidRigel = 0x1202;
constexpr std::uint32_t kPidStereoIr170 = 0x1203;
constexpr std::uint32_t kPid3Di = 0x1204;
constexpr std::uint32_t kPidLeapMotionController2 = 0x1206;

eLeapTrackingMode to_leap_mode(TrackingMode m) {
  switch (m) {
    case TrackingMode::kScreenTop:
      return eLeapTrackingMode_ScreenTop;
    case TrackingMode::kHeadMounted:
      return eLeapTrackingMode_HMD;
    case TrackingMode::kDesktop:
    case TrackingMode::kUnknown:
      break;
  }
  return eLeapTrackingMode_Desktop;
}

TrackingMode from_leap_mode(std::uint32_t m) {
  switch (m) {
    case eLeapTrackingMode_Desktop:
      return TrackingMode::kDesktop;
    case eLeapTrackingMode_HMD:
      return TrackingMode::kHeadMounted;
    case eLeapTrackingMode_ScreenTop:
      return TrackingMode::kScreenTop;
    default:
      break;
  }
  return TrackingMode::kUnknown;
}

struct OpenDevice {
  LEAP_DEVICE handle = nullptr;
  std::string serial;
  std::string model;
  std::uint32_t product_id = 0;  // LEAP_DEVICE_INFO::pid
  // Announced (kAppeared) once subscribed: until then it delivers nothing and is not shown.
  bool subscribed = false;
  int subscribe_attempts = 0;
  std::int64_t retry_at_ns = 0;
  TrackingMode wanted_mode = TrackingMode::kDesktop;
  TrackingMode mode = TrackingMode::kUnknown;  // as the service last reported it
  bool background_refused = false;             // the latest policy answer lacked background frames
  std::int64_t drops_pending = 0;              // dropped frames not yet reported
  std::int64_t drops_reported_ns = 0;
};

// A device announced by the service that could not be opened yet.
struct PendingOpen {
  LEAP_DEVICE_REF ref{};
  int attempts = 0;
  std::int64_t retry_at_ns = 0;
};

}  // namespace

std::string leapc_result_name(std::uint32_t rs) {
  switch (rs) {
    case eLeapRS_Success:
      return "eLeapRS_Success";
    case eLeapRS_UnknownError:
      return "eLeapRS_UnknownError";
    case eLeapRS_InvalidArgument:
      return "eLeapRS_InvalidArgument";
    case eLeapRS_InsufficientResources:
      return "eLeapRS_InsufficientResources";
    case eLeapRS_InsufficientBuffer:
      return "eLeapRS_InsufficientBuffer";
    case eLeapRS_Timeout:
      return "eLeapRS_Timeout";
    case eLeapRS_NotConnected:
      return "eLeapRS_NotConnected";
    case eLeapRS_HandshakeIncomplete:
      return "eLeapRS_HandshakeIncomplete";
    case eLeapRS_UnexpectedClosed:
      return "eLeapRS_UnexpectedClosed";
    case eLeapRS_ConcurrentPoll:
      return "eLeapRS_ConcurrentPoll";
    case eLeapRS_NotAvailable:
      return "eLeapRS_NotAvailable";
    case eLeapRS_NotStreaming:
      return "eLeapRS_NotStreaming";
    case eLeapRS_CannotOpenDevice:
      return "eLeapRS_CannotOpenDevice";
    default:
      break;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "eLeapRS 0x%08X", rs);
  return buf;
}

std::string leapc_status_text(std::uint32_t s) {
  switch (s) {
    case eLeapDeviceStatus_UnknownFailure:
      return "unknown failure";
    case eLeapDeviceStatus_BadCalibration:
      return "bad calibration";
    case eLeapDeviceStatus_BadFirmware:
      return "bad firmware";
    case eLeapDeviceStatus_BadTransport:
      return "bad transport (USB link: use its own port or a powered hub)";
    case eLeapDeviceStatus_BadControl:
      return "bad control";
    default:
      break;
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

std::string leapc_model_name(std::uint32_t pid) {
  switch (pid) {
    case kPidLeapMotionController:
      return "Leap Motion Controller";
    case kPidLeapMotionController2:
      return "Leap Motion Controller 2";
    case kPidStereoIr170:
      return "Stereo IR 170";
    case kPidRigel:
      return "Rigel";
    case kPid3Di:
      return "3Di";
    default:
      break;
  }
  char buf[48];
  std::snprintf(buf, sizeof buf, "Ultraleap device (product id 0x%04X)", pid);
  return buf;
}

struct LeapcSource::Impl {
  LEAP_CONNECTION connection = nullptr;
  std::map<std::uint32_t, OpenDevice> devices;   // by LEAP_DEVICE_REF.id
  std::map<std::uint32_t, PendingOpen> pending;  // announced, not opened yet
  std::set<std::uint32_t> refused;               // ids refused for a duplicate serial
  int service_sessions = 0;                      // connection losses so far

  ~Impl() { close(); }

  void close() {
    for (auto& [id, d] : devices) {
      if (connection != nullptr && d.subscribed) LeapUnsubscribeEvents(connection, d.handle);
      LeapCloseDevice(d.handle);
    }
    devices.clear();
    pending.clear();
    refused.clear();
    if (connection != nullptr) {
      LeapCloseConnection(connection);
      LeapDestroyConnection(connection);
      connection = nullptr;
    }
  }
};

LeapcSource::LeapcSource(LeapcOptions options) : options_(std::move(options)), impl_(std::make_unique<Impl>()) {
  if (options_.max_attempts < 1) options_.max_attempts = 1;
}

LeapcSource::~LeapcSource() {
  stop();
}

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
  // Policies and tracking modes are set per device once each is subscribed (run()): on a
  // multi-device-aware connection the connection-wide calls reach only the primary device.
  stop_ = false;
  running_ = true;
  thread_ = std::thread([this, &sink] { run(sink); });
}

void LeapcSource::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  running_ = false;
  impl_->close();
}

std::optional<std::int64_t> LeapcSource::device_clock_us(std::int64_t host_ns) const {
  if (!running_) return std::nullopt;
  // Read the two clocks back to back; the host clock then carries the reading to `host_ns`.
  const std::int64_t host_now = host_now_ns();
  const std::int64_t leap_now = LeapGetNow();
  return leap_now + (host_ns - host_now) / 1000;
}

void LeapcSource::run(FrameSink& sink) {
  Impl& im = *impl_;
  const std::int64_t retry_ns = static_cast<std::int64_t>(options_.retry_interval_ms) * 1'000'000;
  auto event = [&](DeviceEventKind kind, const std::string& serial, std::string message, std::int64_t count = 0) {
    DeviceEvent e;
    e.kind = kind;
    e.info.serial = serial;
    e.info.backend = "leapc";
    e.message = std::move(message);
    e.count = count;
    e.host_time_ns = host_now_ns();
    sink.on_device_event(e);
  };
  // A message about no device the hub knows yet (or a device refused): shown as it is.
  auto say = [&](std::string message) { event(DeviceEventKind::kNotice, "", std::move(message)); };
  auto find = [&](std::uint32_t id) -> OpenDevice* {
    auto it = im.devices.find(id);
    return it == im.devices.end() ? nullptr : &it->second;
  };
  auto flush_drops = [&](OpenDevice& d, std::int64_t now_ns) {
    if (d.drops_pending == 0) return;
    event(DeviceEventKind::kDroppedFrames, d.serial,
          "the service dropped " + std::to_string(d.drops_pending) + (d.drops_pending == 1 ? " frame" : " frames"),
          d.drops_pending);
    d.drops_pending = 0;
    d.drops_reported_ns = now_ns;
  };
  auto close_device = [&](std::uint32_t id) {
    auto it = im.devices.find(id);
    if (it == im.devices.end()) return;
    if (it->second.subscribed) LeapUnsubscribeEvents(im.connection, it->second.handle);
    LeapCloseDevice(it->second.handle);
    im.devices.erase(it);
  };

  // Subscribed at last: ask for background frames and the tracking mode (both answered by later
  // events), then announce the device.
  auto finish_setup = [&](OpenDevice& d) {
    d.subscribed = true;
    const eLeapRS prs = options_.background_frames
                            ? LeapSetPolicyFlagsEx(im.connection, d.handle, eLeapPolicyFlag_BackgroundFrames, 0)
                            : eLeapRS_Success;
    const eLeapRS mrs = options_.request_tracking_mode
                            ? LeapSetTrackingModeEx(im.connection, d.handle, to_leap_mode(d.wanted_mode))
                            : eLeapRS_Success;
    // Ask for the mode in force too: its answer is a TrackingMode event whatever the service sends
    // for the request, and a listing that changes nothing learns the mode this way. A service
    // without the call leaves the mode unknown, which the Devices tab shows as such.
    LeapGetTrackingModeEx(im.connection, d.handle);
    DeviceEvent e;
    e.kind = DeviceEventKind::kAppeared;
    e.info.serial = d.serial;
    e.info.backend = "leapc";
    e.info.model = d.model;
    e.info.product_id = d.product_id;
    e.host_time_ns = host_now_ns();
    sink.on_device_event(e);
    if (prs != eLeapRS_Success)
      event(DeviceEventKind::kNotice, d.serial,
            "cannot set the background-frames policy (" + leapc_result_name(prs) +
                "); it may stop streaming while another window has focus");
    if (mrs != eLeapRS_Success)
      event(DeviceEventKind::kNotice, d.serial,
            std::string("cannot request ") + tracking_mode_name(d.wanted_mode) + " tracking mode (" +
                leapc_result_name(mrs) + "); it tracks in whatever mode the service has for it");
  };

  auto try_subscribe = [&](std::uint32_t id, OpenDevice& d, std::int64_t now_ns) {
    const eLeapRS rs = LeapSubscribeEvents(im.connection, d.handle);
    if (rs == eLeapRS_Success) {
      finish_setup(d);
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
    d.retry_at_ns = now_ns + retry_ns;
  };

  // Opens an announced device, reads its serial and model and subscribes to it. False when the
  // open failed (the caller keeps it pending).
  auto try_open = [&](const LEAP_DEVICE_REF& ref, std::int64_t now_ns, eLeapRS& rs) -> bool {
    LEAP_DEVICE handle = nullptr;
    rs = LeapOpenDevice(ref, &handle);
    if (rs != eLeapRS_Success) return false;
    LEAP_DEVICE_INFO info{};
    info.size = sizeof info;
    info.serial = nullptr;
    LeapGetDeviceInfo(handle, &info);  // learns serial_length
    std::vector<char> serial(info.serial_length + 1, '\0');
    info.serial = serial.data();
    info.serial_length = static_cast<std::uint32_t>(serial.size());
    std::string serial_text;
    if (LeapGetDeviceInfo(handle, &info) == eLeapRS_Success) serial_text = serial.data();
    if (serial_text.empty()) {
      // Never key on an index alone: the id is only unique within one service session, so the
      // session count goes into the key and a restart never maps another controller onto it.
      serial_text = "leapc-id-" + std::to_string(ref.id);
      if (im.service_sessions > 0) serial_text += "-s" + std::to_string(im.service_sessions + 1);
      say("LeapC: the controller with device id " + std::to_string(ref.id) + " reports no serial; it is called " +
          serial_text + " until the service restarts, so its slot cannot be kept across restarts");
    }
    // Two open devices with one serial (placeholder serials of services before 5.4, a serial
    // the service could not read): taking both would interleave two controllers in one slot.
    for (const auto& [other_id, other] : im.devices) {
      if (other.serial != serial_text) continue;
      LeapCloseDevice(handle);
      im.refused.insert(ref.id);
      say("LeapC: refused the controller with device id " + std::to_string(ref.id) + ": it reports serial " +
          serial_text + ", as device " + std::to_string(other_id) +
          " does. Two controllers cannot share one serial (one slot); update the Ultraleap service (5.4 or newer "
          "reports real serials), or unplug one of them");
      return true;
    }
    OpenDevice& d = im.devices[ref.id];
    d.handle = handle;
    d.serial = serial_text;
    d.model = leapc_model_name(static_cast<std::uint32_t>(info.pid));
    d.product_id = static_cast<std::uint32_t>(info.pid);
    d.wanted_mode = tracking_mode_for_serial(options_.layout, serial_text);
    try_subscribe(ref.id, d, now_ns);
    return true;
  };

  auto open_or_queue = [&](LEAP_DEVICE_REF ref, std::int64_t now_ns) {
    eLeapRS rs = eLeapRS_Success;
    PendingOpen& p = im.pending[ref.id];
    p.ref = ref;
    if (try_open(ref, now_ns, rs)) {
      im.pending.erase(ref.id);
      return;
    }
    ++p.attempts;
    const std::string what = "LeapC: cannot open device " + std::to_string(ref.id) + " (" + leapc_result_name(rs) + ")";
    if (p.attempts >= options_.max_attempts) {
      say(what + "; gave up after " + std::to_string(p.attempts) + " attempts: re-plug it");
      im.pending.erase(ref.id);
      return;
    }
    if (p.attempts == 1) say(what + "; trying again");
    p.retry_at_ns = now_ns + retry_ns;
  };

  // Between polls: retries that are due, dropped frames that waited a second.
  auto housekeeping = [&](std::int64_t now_ns) {
    std::vector<std::uint32_t> due;
    for (const auto& [id, p] : im.pending)
      if (p.retry_at_ns <= now_ns) due.push_back(id);
    for (const std::uint32_t id : due) open_or_queue(im.pending[id].ref, now_ns);
    due.clear();
    for (const auto& [id, d] : im.devices)
      if (!d.subscribed && d.retry_at_ns <= now_ns) due.push_back(id);
    for (const std::uint32_t id : due)
      if (OpenDevice* d = find(id)) try_subscribe(id, *d, now_ns);
    for (auto& [id, d] : im.devices)
      if (d.drops_pending > 0 && now_ns - d.drops_reported_ns >= kDropReportIntervalNs) flush_drops(d, now_ns);
  };

  int consecutive_errors = 0;
  bool told_unreachable = false;
  while (!stop_) {
    LEAP_CONNECTION_MESSAGE msg;
    const eLeapRS rs = LeapPollConnection(im.connection, options_.poll_timeout_ms, &msg);
    housekeeping(host_now_ns());
    if (rs == eLeapRS_Timeout) continue;
    if (rs != eLeapRS_Success) {
      // The service may not be running yet, or restarting: say so now and then, keep polling.
      if (consecutive_errors++ % 50 == 0) {
        if (rs == eLeapRS_NotConnected || rs == eLeapRS_NotAvailable || rs == eLeapRS_HandshakeIncomplete) {
          say("waiting for the Ultraleap service (LeapC: " + leapc_result_name(rs) + "): is it installed and running?");
          told_unreachable = true;
        } else {
          say("LeapC poll failed: " + leapc_result_name(rs));
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    consecutive_errors = 0;
    const std::int64_t received_ns = host_now_ns();
    switch (msg.type) {
      case eLeapEventType_Connection:
        if (told_unreachable) {
          say("connected to the Ultraleap service");
          told_unreachable = false;
        }
        if (msg.connection_event != nullptr && msg.connection_event->flags != 0) {
          std::string what;
          if (msg.connection_event->flags & eLeapServiceState_LowFpsDetected) what += " low frame rate detected;";
          if (msg.connection_event->flags & eLeapServiceState_PoorPerformancePause)
            what += " paused for poor performance;";
          if (msg.connection_event->flags & eLeapServiceState_TrackingErrorUnknown) what += " tracking error;";
          say("Ultraleap service:" + what);
        }
        break;
      case eLeapEventType_ConnectionLost: {
        // Every device is gone until the service is back; it re-sends Device events then, with
        // ids that start afresh.
        for (auto& [id, d] : im.devices) {
          flush_drops(d, received_ns);
          if (d.subscribed) event(DeviceEventKind::kLost, d.serial, "connection to the Ultraleap service lost");
          LeapCloseDevice(d.handle);
        }
        im.devices.clear();
        im.pending.clear();
        im.refused.clear();
        ++im.service_sessions;
        break;
      }
      case eLeapEventType_Device: {
        const LEAP_DEVICE_REF ref = msg.device_event->device;
        // Already open, being retried or refused: a repeated announcement changes nothing.
        if (im.devices.count(ref.id) != 0 || im.pending.count(ref.id) != 0 || im.refused.count(ref.id) != 0) break;
        open_or_queue(ref, received_ns);
        break;
      }
      case eLeapEventType_DeviceLost: {
        const std::uint32_t id = msg.device_event->device.id;
        im.pending.erase(id);
        im.refused.erase(id);
        OpenDevice* d = find(id);
        if (d == nullptr) break;
        const std::string serial = d->serial;
        const bool announced = d->subscribed;
        flush_drops(*d, received_ns);
        close_device(id);
        if (announced) event(DeviceEventKind::kLost, serial, "device lost");
        break;
      }
      case eLeapEventType_DeviceFailure: {
        // The event names its device by handle (hDevice, "may be NULL"); else the message's id.
        const OpenDevice* failed = nullptr;
        if (msg.device_failure_event->hDevice != nullptr)
          for (const auto& [id, d] : im.devices)
            if (d.handle == msg.device_failure_event->hDevice) failed = &d;
        if (failed == nullptr) failed = find(msg.device_id);
        event(DeviceEventKind::kFailure, failed ? failed->serial : "",
              (failed ? "" : "a device failed: ") + leapc_status_text(msg.device_failure_event->status));
        break;
      }
      case eLeapEventType_DeviceStatusChange: {
        const auto* ev = msg.device_status_change_event;
        const OpenDevice* d = find(ev->device.id != 0 ? ev->device.id : msg.device_id);
        const bool failure = (ev->status & 0xE8010000u) == 0xE8010000u;
        event(failure ? DeviceEventKind::kFailure : DeviceEventKind::kNotice, d ? d->serial : "",
              "status " + leapc_status_text(ev->last_status) + " → " + leapc_status_text(ev->status));
        break;
      }
      case eLeapEventType_Policy: {
        // The service's answer to LeapSetPolicyFlagsEx (or a change made elsewhere): the policies
        // now in force. Background frames missing means it was refused or taken away.
        if (!options_.background_frames || msg.policy_event == nullptr) break;
        const bool granted = (msg.policy_event->current_policy & eLeapPolicyFlag_BackgroundFrames) != 0;
        // Only answers naming one of our devices count: the connection-wide policies (device_id
        // 0) are not the ones this backend sets.
        for (auto& [id, d] : im.devices) {
          if (!d.subscribed || id != msg.device_id) continue;
          if (!granted && !d.background_refused) {
            event(DeviceEventKind::kNotice, d.serial,
                  "the service refused the background-frames policy: it may stop streaming while another window "
                  "has focus");
          } else if (granted && d.background_refused) {
            event(DeviceEventKind::kNotice, d.serial, "background-frames policy granted");
          }
          d.background_refused = !granted;
        }
        break;
      }
      case eLeapEventType_TrackingMode: {
        OpenDevice* d = find(msg.device_id);
        if (d == nullptr || !d->subscribed || msg.tracking_mode_event == nullptr) break;
        const TrackingMode mode =
            from_leap_mode(static_cast<std::uint32_t>(msg.tracking_mode_event->current_tracking_mode));
        if (mode == d->mode) break;
        d->mode = mode;
        DeviceEvent e;
        e.kind = DeviceEventKind::kTrackingMode;
        e.info.serial = d->serial;
        e.info.backend = "leapc";
        e.info.tracking_mode = tracking_mode_name(mode);
        if (options_.request_tracking_mode && mode != d->wanted_mode)
          e.message = std::string("not the ") + tracking_mode_name(d->wanted_mode) +
                      " mode its place in the layout needs: it tracks the hand under the wrong assumption (the "
                      "control panel or another program may have set it)";
        e.host_time_ns = received_ns;
        sink.on_device_event(e);
        break;
      }
      case eLeapEventType_DroppedFrame: {
        OpenDevice* d = find(msg.device_id);
        if (d == nullptr || !d->subscribed) break;
        ++d->drops_pending;
        if (received_ns - d->drops_reported_ns >= kDropReportIntervalNs) flush_drops(*d, received_ns);
        break;
      }
      case eLeapEventType_Tracking: {
        const OpenDevice* d = find(msg.device_id);
        if (d == nullptr || !d->subscribed) break;  // not one of ours (or a system-wide message)
        const LEAP_TRACKING_EVENT& t = *msg.tracking_event;
        SourceFrame f;
        f.serial = d->serial;
        f.host_receive_ns = received_ns;
        // The image frame id, as the study's files hold it: it skips when the service drops
        // images as well as when this client polls too slowly (tracking_frame_id skips only then).
        f.frame.frame_id = t.info.frame_id;
        f.frame.timestamp_us = t.info.timestamp;
        f.frame.frame_rate_hz = t.framerate;
        f.frame.points.fill(Vec3::Zero());
        const LEAP_HAND* chosen = nullptr;
        for (std::uint32_t i = 0; i < t.nHands && chosen == nullptr; ++i)
          if (to_hand_type(t.pHands[i].type) == options_.wanted_hand) chosen = &t.pHands[i];
        // The only hand in view called the other side is the subject's hand misclassified (the
        // study's subjects held one hand in the rig): keep it, marked, rather than lose the frame.
        if (chosen == nullptr && t.nHands == 1) {
          chosen = &t.pHands[0];
          f.other_side_hand = true;
        }
        if (chosen != nullptr) {
          copy_hand(*chosen, f.frame);
          f.frame.hand_present = true;
          f.hand_type = to_hand_type(chosen->type);
          f.confidence = chosen->confidence;
        }
        sink.on_frame(f);
        break;
      }
      default:
        break;
    }
  }
  // Nothing counted is lost at the end either.
  const std::int64_t end_ns = host_now_ns();
  for (auto& [id, d] : im.devices) flush_drops(d, end_ns);
}

std::vector<DeviceInfo> leapc_list_devices(std::uint32_t wait_ms) {
  struct Collect final : FrameSink {
    std::mutex m;
    std::vector<DeviceInfo> devices;
    void on_device_event(const DeviceEvent& e) override {
      std::lock_guard lock(m);
      if (e.kind == DeviceEventKind::kAppeared) devices.push_back(e.info);
      if (e.kind == DeviceEventKind::kTrackingMode)
        for (auto& d : devices)
          if (d.serial == e.info.serial) d.tracking_mode = e.info.tracking_mode;
    }
    void on_frame(const SourceFrame&) override {}
  } collect;
  LeapcOptions options;
  options.request_tracking_mode = false;
  LeapcSource source(options);
  source.start(collect);
  std::this_thread::sleep_for(std::chrono::milliseconds(wait_ms));
  source.stop();
  std::lock_guard lock(collect.m);
  return collect.devices;
}

}  // namespace lmc::devices
