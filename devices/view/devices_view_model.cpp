#include "devices/view/devices_view_model.h"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "devices/host_clock.h"
#include "devices/record/trial_name.h"

namespace lmc::devices {
namespace {
constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kStalledMs = 500.0;  // no frame for this long while connected: something is wrong
constexpr size_t kMaxMessages = 200;
}  // namespace

std::array<float, 3> device_colour(int index) {
  static const std::array<std::array<float, 3>, 8> colours = {{{0.90F, 0.30F, 0.25F},
                                                               {0.25F, 0.65F, 0.95F},
                                                               {0.35F, 0.80F, 0.35F},
                                                               {0.95F, 0.75F, 0.20F},
                                                               {0.75F, 0.45F, 0.90F},
                                                               {0.20F, 0.85F, 0.80F},
                                                               {0.95F, 0.50F, 0.75F},
                                                               {0.70F, 0.70F, 0.70F}}};
  return colours[static_cast<size_t>(((index % 8) + 8) % 8)];
}

const std::vector<std::pair<int, int>>& hand_bones() {
  static const std::vector<std::pair<int, int>> bones = [] {
    std::vector<std::pair<int, int>> b;
    b.emplace_back(kElbow, kWrist);
    for (int d = 0; d < kNumDigits; ++d) {
      b.emplace_back(kWrist, digit_point(d, 0));
      for (int j = 0; j + 1 < kJointsPerDigit; ++j) b.emplace_back(digit_point(d, j), digit_point(d, j + 1));
    }
    // Knuckle line across the MCP joints.
    for (int d = 1; d + 1 < kNumDigits; ++d) b.emplace_back(digit_point(d, 1), digit_point(d + 1, 1));
    return b;
  }();
  return bones;
}

Eigen::Vector3d ViewCamera::eye() const {
  const double yaw = yaw_deg * kDegToRad;
  const double pitch = pitch_deg * kDegToRad;
  return target + distance_mm * Eigen::Vector3d(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                                                std::cos(yaw) * std::cos(pitch));
}

std::optional<Eigen::Vector2d> ViewCamera::project(const Eigen::Vector3d& world, double x0, double y0, double width,
                                                   double height) const {
  const Eigen::Vector3d e = eye();
  const Eigen::Vector3d forward = (target - e).normalized();
  Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitY());
  if (right.norm() < 1e-9) right = Eigen::Vector3d::UnitX();
  right.normalize();
  const Eigen::Vector3d up = right.cross(forward);
  const Eigen::Vector3d v = world - e;
  const double depth = v.dot(forward);
  if (depth < 1.0) return std::nullopt;
  const double f = 0.5 * height / std::tan(0.5 * fov_y_deg * kDegToRad);
  return Eigen::Vector2d(x0 + 0.5 * width + f * v.dot(right) / depth, y0 + 0.5 * height - f * v.dot(up) / depth);
}

DevicesViewModel::DevicesViewModel(Layout layout) : layout_(std::move(layout)) {}

DevicesViewModel::~DevicesViewModel() { stop(); }

void DevicesViewModel::set_layout(Layout layout) {
  stop();
  layout_ = std::move(layout);
}

std::string DevicesViewModel::start(const std::string& backend, const SimConfig& sim) {
  stop();
  try {
    const SourceSpec spec = parse_source_spec(backend);
    SourceSettings settings;
    settings.layout = layout_;
    settings.sim = sim;
    auto hub = std::make_unique<DeviceHub>(layout_);
    hub->add_source(make_source(spec, settings));
    hub->start();
    hub_ = std::move(hub);
    backend_ = backend;
    started_ns_ = host_now_ns();
    messages_.push_back("started " + backend);
  } catch (const std::exception& e) {
    messages_.push_back(std::string("cannot start ") + backend + ": " + e.what());
    return e.what();
  }
  return {};
}

void DevicesViewModel::stop() {
  if (recorder_) stop_recording();
  if (hub_) {
    hub_->stop();
    hub_.reset();
    messages_.push_back("stopped " + backend_);
  }
  rows_.clear();
  hands_.clear();
  all_streaming_ = false;
}

double DevicesViewModel::running_seconds() const {
  return hub_ ? static_cast<double>(host_now_ns() - started_ns_) / 1e9 : 0.0;
}

void DevicesViewModel::refresh() {
  if (!hub_) return;
  // A write error stops the trial; the recorder has kept what it wrote.
  if (recorder_ && recorder_->failed()) stop_recording();
  for (auto& m : hub_->take_messages()) messages_.push_back(std::move(m));
  if (messages_.size() > kMaxMessages) messages_.erase(messages_.begin(), messages_.end() - kMaxMessages);
  const HubSnapshot snap = hub_->snapshot();
  const Layout& hub_layout = hub_->layout();
  rows_.clear();
  hands_.clear();
  int streaming_slots = 0;
  for (const DeviceStatus& s : snap.devices) {
    DeviceRow r;
    r.serial = s.serial;
    r.slot = s.slot;
    r.slot_index = s.slot_index;
    r.backend = s.backend;
    r.rate_hz = s.rate_hz;
    r.age_ms = s.latest_frame_age_ms;
    r.hand_present = s.hand_present;
    r.frames = s.frames_received;
    r.dropped = s.frames_dropped + s.frames_dropped_recorder;
    r.colour = s.slot_index >= 0 ? s.slot_index : 7;
    if (!s.connected) r.status = "disconnected";
    else if (s.slot_index < 0) r.status = "unassigned";
    else if (s.frames_received == 0) r.status = "waiting";
    else if (r.age_ms > kStalledMs) r.status = "stalled";
    else r.status = s.hand_present ? "streaming" : "no hand";
    // The study saw 11–34 Hz with four devices; below that, suspect USB bandwidth or power.
    r.warn = r.status == "disconnected" || r.status == "stalled" || (s.connected && s.frames_received > 0 && r.rate_hz < 10);
    if (s.slot_index >= 0 && s.connected && s.frames_received > 0 && r.age_ms <= kStalledMs) ++streaming_slots;
    if (s.slot_index >= 0 && s.hand_present && s.latest && s.connected &&
        s.slot_index < hub_layout.device_count()) {
      LiveHand h;
      h.colour = s.slot_index;
      h.slot = s.slot;
      const LayoutDevice& ld = hub_layout.devices[static_cast<size_t>(s.slot_index)];
      for (int p = 0; p < kNumHandPoints; ++p) {
        const Vec3& q = s.latest->point(p);
        h.world[static_cast<size_t>(p)] =
            (p == kPalmNormal || p == kPalmDirection) ? Vec3(ld.pose.rotation() * q) : ld.to_world(q);
      }
      hands_.push_back(h);
    }
    rows_.push_back(std::move(r));
  }
  all_streaming_ = streaming_slots >= layout_.device_count() && running_seconds() >= 1.2;
}

bool DevicesViewModel::all_streaming() const { return all_streaming_; }

std::vector<std::string> DevicesViewModel::slot_choices() const {
  std::vector<std::string> out;
  for (const auto& d : layout_.devices) out.push_back(d.slot);
  return out;
}

std::string DevicesViewModel::assign(const std::string& serial, const std::string& slot) {
  if (!hub_) return "no backend running";
  std::string err = hub_->assign(serial, slot);
  if (err.empty()) layout_ = hub_->layout();  // the binding is part of the layout now
  return err;
}

std::string DevicesViewModel::start_recording(const std::filesystem::path& dir, const std::string& trial) {
  if (!hub_) return "start a backend first";
  if (recorder_) return "already recording";
  if (auto why = validate_trial_name(trial); !why.empty()) return why;
  // Never overwrite (the TrialEngine's rule): pressing Record again with the same name records
  // <trial>-2, <trial>-3, … beside the earlier takes.
  std::string name;
  try {
    name = next_free_trial_name(dir, trial);
  } catch (const std::exception& e) {
    return e.what();
  }
  RecorderConfig rc;
  rc.output_dir = dir;
  rc.trial = name;
  rc.layout = hub_->layout();
  rc.backend = backend_;
  try {
    auto rec = std::make_unique<Recorder>(rc);
    rec->start();
    recorder_ = std::move(rec);
    hub_->set_consumer(recorder_.get());
  } catch (const std::exception& e) {
    return e.what();
  }
  recording_trial_ = name;
  messages_.push_back("recording " + name + " to " + dir.string() +
                      (name == trial ? std::string() : " (" + trial + " is taken)"));
  return {};
}

std::string DevicesViewModel::stop_recording() {
  if (!recorder_) return "not recording";
  if (hub_) hub_->set_consumer(nullptr);
  const RecorderStatus st = recorder_->stop(hub_ ? hub_->serial_to_slot() : std::vector<std::pair<std::string, std::string>>{});
  const std::string file = recorder_->paths().recording.string();
  recorder_.reset();
  std::string summary = st.state == RecorderState::kFailed || st.state == RecorderState::kAborted
                            ? st.error
                            : "recorded " + std::to_string(st.frames_written) + " frames from " +
                                  std::to_string(st.devices.size()) + " devices to " + file;
  messages_.push_back(summary);
  return summary;
}

std::optional<RecorderStatus> DevicesViewModel::recording_status() const {
  if (!recorder_) return std::nullopt;
  return recorder_->status();
}

}  // namespace lmc::devices
