#include "devices/leapc/leapc_source.h"

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <utility>

#include "core/common/error.h"
#include "devices/host_clock.h"
#include "devices/leapc/leapc_session.h"

namespace lmc::devices {
namespace {

// Product ids as LeapC numbers them (LEAP_DEVICE_INFO::pid); the LMC2's appeared with 5.11.
constexpr std::uint32_t kPidLeapMotionController = 0x0003;
constexpr std::uint32_t kPidRigel = 0x1202;
constexpr std::uint32_t kPidStereoIr170 = 0x1203;
constexpr std::uint32_t kPid3Di = 0x1204;
constexpr std::uint32_t kPidLeapMotionController2 = 0x1206;

}  // namespace

std::string leapc_result_name(std::uint32_t rs) {
  switch (rs) {
    case leapc::kSuccess:
      return "eLeapRS_Success";
    case leapc::kUnknownError:
      return "eLeapRS_UnknownError";
    case leapc::kInvalidArgument:
      return "eLeapRS_InvalidArgument";
    case leapc::kInsufficientResources:
      return "eLeapRS_InsufficientResources";
    case leapc::kInsufficientBuffer:
      return "eLeapRS_InsufficientBuffer";
    case leapc::kTimeout:
      return "eLeapRS_Timeout";
    case leapc::kNotConnected:
      return "eLeapRS_NotConnected";
    case leapc::kHandshakeIncomplete:
      return "eLeapRS_HandshakeIncomplete";
    case leapc::kUnexpectedClosed:
      return "eLeapRS_UnexpectedClosed";
    case leapc::kConcurrentPoll:
      return "eLeapRS_ConcurrentPoll";
    case leapc::kNotAvailable:
      return "eLeapRS_NotAvailable";
    case leapc::kNotStreaming:
      return "eLeapRS_NotStreaming";
    case leapc::kCannotOpenDevice:
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
    case leapc::kStatusUnknownFailure:
      return "unknown failure";
    case leapc::kStatusBadCalibration:
      return "bad calibration";
    case leapc::kStatusBadFirmware:
      return "bad firmware";
    case leapc::kStatusBadTransport:
      return "bad transport (USB link: use its own port or a powered hub)";
    case leapc::kStatusBadControl:
      return "bad control";
    default:
      break;
  }
  std::string out;
  if (s & leapc::kStatusStreaming) out += "streaming ";
  if (s & leapc::kStatusPaused) out += "paused ";
  if (s & leapc::kStatusRobust) out += "robust mode ";
  if (s & leapc::kStatusSmudged) out += "smudged ";
  if (s & leapc::kStatusLowResource) out += "low resource ";
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

// The poll thread's share: the session, and whether the thread has finished or was left to
// finish alone by a stop() that could not wait for it.
struct LeapcSource::Impl {
  explicit Impl(std::shared_ptr<const LeapcLibrary> library, const LeapcOptions& options)
      : session(std::move(library), options) {}
  LeapcSession session;
  std::mutex mutex;
  std::condition_variable cv;
  bool done = false;
  bool abandoned = false;
};

LeapcSource::LeapcSource(LeapcOptions options) : options_(std::move(options)) {
  if (options_.max_attempts < 1) options_.max_attempts = 1;
}

LeapcSource::~LeapcSource() {
  stop();
}

void LeapcSource::start(FrameSink& sink) {
  if (thread_.joinable()) return;
  // Searched at every start, so a library installed since the last one is found (Reconnect).
  LeapcSearchResult found = find_leapc();
  if (!found.library) throw Error("LeapC: " + found.failure_text());
  auto impl = std::make_shared<Impl>(found.library, options_);
  impl->session.open();
  // Policies and tracking modes are set per device once each is subscribed: on a
  // multi-device-aware connection the connection-wide calls reach only the primary device.
  {
    std::lock_guard lock(impl_mutex_);
    impl_ = impl;
  }
  thread_ = std::thread([impl, &sink] {
    impl->session.run(sink);
    std::lock_guard lock(impl->mutex);
    impl->done = true;
    if (impl->abandoned) impl->session.destroy();
    impl->cv.notify_all();
  });
}

void LeapcSource::stop() {
  if (!thread_.joinable()) return;
  const std::shared_ptr<Impl> impl = current_impl();
  Impl& im = *impl;
  // Close first, then wait (bounded): a poll can block past its timeout, and closing ends it.
  im.session.request_stop();
  std::unique_lock lock(im.mutex);
  if (im.cv.wait_for(lock, std::chrono::milliseconds(options_.stop_timeout_ms), [&] { return im.done; })) {
    lock.unlock();
    thread_.join();
    im.session.destroy();
  } else {
    im.abandoned = true;  // the thread destroys the connection when LeapC lets it go
    im.session.silence();
    lock.unlock();
    thread_.detach();
  }
  std::lock_guard impl_lock(impl_mutex_);
  impl_.reset();
}

std::shared_ptr<LeapcSource::Impl> LeapcSource::current_impl() const {
  std::lock_guard lock(impl_mutex_);
  return impl_;
}

std::optional<std::int64_t> LeapcSource::device_clock_us(std::int64_t host_ns) const {
  const std::shared_ptr<Impl> impl = current_impl();
  if (!impl) return std::nullopt;
  const leapc::GetNowFn get_now = impl->session.library().api.get_now;
  // Host, Leap, host: the narrowest of a few brackets, read at its middle. A bracket a thread
  // switch widened is never the narrowest.
  constexpr int kBrackets = 5;
  std::int64_t best_width = -1;
  std::int64_t best_leap = 0;
  std::int64_t best_mid = 0;
  for (int i = 0; i < kBrackets; ++i) {
    const std::int64_t h0 = host_now_ns();
    const std::int64_t leap = get_now();
    const std::int64_t h1 = host_now_ns();
    if (best_width < 0 || h1 - h0 < best_width) {
      best_width = h1 - h0;
      best_leap = leap;
      best_mid = h0 + (h1 - h0) / 2;
    }
  }
  clock_uncertainty_us_ = (best_width / 2 + 999) / 1000;
  return best_leap + (host_ns - best_mid) / 1000;
}

std::optional<std::int64_t> LeapcSource::device_clock_uncertainty_us() const {
  const std::int64_t u = clock_uncertainty_us_;
  return u < 0 ? std::nullopt : std::optional<std::int64_t>(u);
}

std::vector<DeviceInfo> leapc_list_devices(std::uint32_t wait_ms, std::vector<std::string>* notices) {
  struct Collect final : FrameSink {
    std::mutex m;
    std::vector<DeviceInfo> devices;
    std::vector<std::string> notices;
    void on_device_event(const DeviceEvent& e) override {
      std::lock_guard lock(m);
      if (e.kind == DeviceEventKind::kAppeared) devices.push_back(e.info);
      if (e.kind == DeviceEventKind::kTrackingMode)
        for (auto& d : devices)
          if (d.serial == e.info.serial) d.tracking_mode = e.info.tracking_mode;
      if (e.kind == DeviceEventKind::kNotice && e.info.serial.empty()) notices.push_back(e.message);
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
  if (notices != nullptr) *notices = collect.notices;
  return collect.devices;
}

}  // namespace lmc::devices
