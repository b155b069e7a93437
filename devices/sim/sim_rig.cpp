#include "devices/sim/sim_rig.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "core/common/angles.h"
#include "core/common/error.h"
#include "core/hand/reference_poses.h"
#include "core/io/pose_set_tsv.h"
#include "core/io/sensor_catalogue_json.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_explain.h"
#include "devices/sim/controller_hand_model.h"
#include "devices/tracking_mode.h"

namespace lmc::devices {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct PalmBasis {
  Vec3 origin;
  Eigen::Matrix3d axes;  // columns: direction, normal, direction × normal
};

std::optional<PalmBasis> palm_basis(const HandFrame& f) {
  const Vec3 dir = f.point(kPalmDirection);
  const Vec3 nrm = f.point(kPalmNormal);
  const Vec3 side = dir.cross(nrm);
  if (dir.norm() < 1e-9 || nrm.norm() < 1e-9 || side.norm() < 1e-9) return std::nullopt;
  PalmBasis b;
  b.origin = f.point(kPalm);
  b.axes.col(0) = dir.normalized();
  b.axes.col(2) = side.normalized();
  b.axes.col(1) = b.axes.col(2).cross(b.axes.col(0));
  return b;
}

std::uint64_t mix(std::uint64_t seed, std::uint64_t k) {
  // splitmix64: independent, reproducible streams per device from one seed.
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (k + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// The serial a controller reports: the layout's, or one made from the seed and its slot.
std::string sim_serial(const SimConfig& config, const LayoutDevice& ld, size_t i) {
  if (ld.serial) return *ld.serial;
  return config.serial_prefix + "-" + ld.slot + "-" + std::to_string(10000 + (mix(config.seed, 100 + i) % 90000));
}

// What the controller reports itself as: its slot's model's hardware (the study's model is the
// original controller), or the configured stand-in.
void describe_sim_hardware(DeviceInfo& info, const SimConfig& config, const LayoutDevice& ld) {
  const SensorCatalogue& catalogue = sensor_catalogue();
  const SensorSpec* reported = catalogue.find(config.stand_in_model.empty() ? ld.model : config.stand_in_model);
  if (reported && !reported->leapc_product_ids.empty()) {
    if (const SensorSpec* hw = catalogue.for_product_id(reported->leapc_product_ids.front())) reported = hw;
  }
  info.model = "simulated " + (reported ? reported->name : std::string("Leap Motion Controller"));
  info.product_id = reported && !reported->leapc_product_ids.empty() ? reported->leapc_product_ids.front() : 0;
}

// The translation error the configuration gives the slot, before any random part.
Vec3 configured_calibration(const SimConfig& config, const LayoutDevice& ld) {
  switch (config.calibration) {
    case SimConfig::Calibration::kLayout:
      return ld.offset_mm;
    case SimConfig::Calibration::kNone:
      return Vec3::Zero();
    case SimConfig::Calibration::kCustom: {
      auto it = config.calibration_offsets_mm.find(ld.slot);
      return it == config.calibration_offsets_mm.end() ? Vec3::Zero() : it->second;
    }
  }
  return Vec3::Zero();
}

// Rotation error about the device's own origin (sim_config.h), drawn from a stream of its own so
// that the rates, noise and elbow of a configuration without it do not change. The random part
// also moves `calibration`.
Eigen::Matrix3d calibration_turn(const SimConfig& config, const LayoutDevice& ld, size_t i, Vec3& calibration) {
  Eigen::Matrix3d turn = Eigen::Matrix3d::Identity();
  if (auto it = config.calibration_rotations_deg.find(ld.slot); it != config.calibration_rotations_deg.end()) {
    DevicePose angles;
    angles.rx_deg = it->second.x();
    angles.ry_deg = it->second.y();
    angles.rz_deg = it->second.z();
    turn = angles.rotation();
  }
  if (config.calibration_random_translation_mm > 0 || config.calibration_random_rotation_deg > 0) {
    std::mt19937_64 cal(mix(config.calibration_seed.value_or(config.seed), 200 + i));
    std::normal_distribution<double> gauss(0, 1);
    std::uniform_real_distribution<double> u01(0, 1);
    const Vec3 dir = Vec3(gauss(cal), gauss(cal), gauss(cal)).normalized();
    calibration += dir * (u01(cal) * config.calibration_random_translation_mm);
    const Vec3 axis = Vec3(gauss(cal), gauss(cal), gauss(cal)).normalized();
    const double angle = u01(cal) * config.calibration_random_rotation_deg * kRadPerDeg;
    turn = Eigen::AngleAxisd(angle, axis).toRotationMatrix() * turn;
  }
  return turn;
}

// The paper saw one device's elbow 10–20 mm off in y after realignment; every simulated device
// gets its own constant error of that size, mostly along its y axis.
Vec3 draw_elbow_error(const SimConfig& config, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> mag(config.elbow_error_min_mm, config.elbow_error_max_mm);
  std::normal_distribution<double> dir(0, 0.3);
  std::uniform_real_distribution<double> u01(0, 1);
  Vec3 e(dir(rng), (u01(rng) < 0.5 ? -1.0 : 1.0), dir(rng));
  return e.normalized() * mag(rng);
}

}  // namespace

struct SimRig::Device {
  int index = 0;
  DeviceInfo info;
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  Vec3 origin = Vec3::Zero();  // t + calibration error
  Vec3 calibration = Vec3::Zero();
  DeviceView view;
  std::mt19937_64 rng;
  double rate_hz = 20;
  double rate_scale = 1.0;  // the model's nominal rate over the study controller's
  double noise_sigma_mm = kDefaultPositionNoiseSdMm;
  double next_time_s = 0;
  double last_time_s = -1;
  double reported_rate_hz = 0;
  std::int64_t frame_id = 0;
  Vec3 elbow_error = Vec3::Zero();  // device frame
  std::array<std::array<Vec3, kJointsPerDigit>, kNumDigits> last_seen_local{};
  std::array<bool, kNumDigits> seen{};
  bool connected = true;
  std::vector<SimUnplug> unplugs;
  std::optional<ControllerHandModel> hand_model;  // study errors (study_errors.h), when enabled
};

SimRig::SimRig(Layout layout, SimConfig config)
    : layout_(std::move(layout)), config_(std::move(config)), model_(config_.hand_length_mm, config_.hand_breadth_mm) {
  if (layout_.devices.empty()) throw Error("simulated rig: the layout has no devices");
  marker_map_ = std::make_unique<TruthMarkerMap>(default_vicon_mapping());
  placement_ = reference_placement(model_, config_.orientation);
  if (!config_.pose_set_path.empty()) {
    pose_set_ = load_pose_set(config_.pose_set_path);
    if (pose_set_->frames.empty()) throw Error(ErrorLocation(config_.pose_set_path), "pose set has no frames");
  }
  // Each controller sees through its own model's pyramid; a configured range replaces every far range.
  for (const auto& dev : layout_.devices) {
    VisibilityParams p = VisibilityParams::from_sensor(dev.sensor, config_.phalanx_radius_mm);
    if (config_.range_mm > 0) p.range_mm = config_.range_mm;
    visibility_.push_back(make_limits(p));
  }

  // The internal model's "neutral" finger: the open hand, in palm coordinates.
  HandFrame open = model_.pose(motion_angles(HandMotion::kOpen, 0.0));
  marker_map_->make_consistent(open);
  if (auto b = palm_basis(open)) {
    for (int dg = 0; dg < kNumDigits; ++dg)
      for (int j = 0; j < kJointsPerDigit; ++j)
        neutral_local_[static_cast<size_t>(dg)][static_cast<size_t>(j)] =
            b->axes.transpose() * (open.point(digit_point(dg, j)) - b->origin);
  }
  if (!pose_set_ && config_.motion == HandMotion::kOpen && config_.sway_mm == 0.0) still_truth_ = truth_at(0.0);
  std::mt19937_64 base(mix(config_.seed, 1000));
  std::uniform_real_distribution<double> phase(0, kTwoPi);
  for (auto& p : sway_phase_) p = phase(base);

  for (size_t i = 0; i < layout_.devices.size(); ++i) {
    const LayoutDevice& ld = layout_.devices[i];
    auto d = std::make_unique<Device>();
    d->index = static_cast<int>(i);
    d->rng.seed(mix(config_.seed, i));
    d->info.serial = sim_serial(config_, ld, i);
    d->info.backend = "sim";
    describe_sim_hardware(d->info, config_, ld);
    // The study's shared-bus rates (rate_min_hz…rate_max_hz) are for its 120 Hz controllers; a model
    // with another nominal rate runs proportionally faster or slower.
    const SensorCatalogue& catalogue = sensor_catalogue();
    const SensorSpec* own = catalogue.find(ld.model);
    const SensorSpec* study = catalogue.find(kStudySensorId);
    d->rate_scale = own && study ? own->frame_rate_hz / study->frame_rate_hz : 1.0;
    d->noise_sigma_mm = sim_noise_sigma_mm(config_, own);
    d->info.tracking_mode = tracking_mode_name(tracking_mode_for_pose(ld.pose));
    d->calibration = configured_calibration(config_, ld);
    const Eigen::Matrix3d turn = calibration_turn(config_, ld, i, d->calibration);
    d->r = turn * ld.pose.rotation();
    d->origin = ld.pose.translation() + d->calibration;
    DevicePose true_pose = ld.pose;
    true_pose.set_rotation(d->r);
    d->view = DeviceView::from_pose(true_pose, d->calibration);
    std::uniform_real_distribution<double> rate(config_.rate_min_hz * d->rate_scale,
                                                config_.rate_max_hz * d->rate_scale);
    d->rate_hz = rate(d->rng);
    std::uniform_real_distribution<double> u01(0, 1);
    d->next_time_s = u01(d->rng) / d->rate_hz;
    d->frame_id = 100 + static_cast<std::int64_t>(d->rng() % 900);
    if (config_.elbow_error) d->elbow_error = draw_elbow_error(config_, d->rng);
    if (config_.hand_model_error.enabled) {
      // Its own stream of the calibration seed: a controller keeps its hand model for a session,
      // and nothing else the rig draws changes.
      d->hand_model = draw_controller_hand_model(config_.hand_model_error,
                                                 mix(config_.calibration_seed.value_or(config_.seed), 300 + i));
    }
    for (const auto& u : config_.unplugs)
      if (u.slot == ld.slot) d->unplugs.push_back(u);
    infos_.push_back(d->info);
    devices_.push_back(std::move(d));
  }
}

SimRig::~SimRig() = default;

Eigen::Vector3d SimRig::calibration_error(int device) const {
  return devices_.at(static_cast<size_t>(device))->calibration;
}

double SimRig::noise_sigma_mm(int device) const {
  return devices_.at(static_cast<size_t>(device))->noise_sigma_mm;
}

Eigen::Isometry3d SimRig::true_device_to_world(int device) const {
  const Device& d = *devices_.at(static_cast<size_t>(device));
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = d.r;
  t.translation() = d.origin;
  return t;
}

HandFrame SimRig::truth_at(double t) const {
  if (still_truth_) return *still_truth_;
  // The motion's own clock stands at 0 while the hand holds its start pose; the sway does not stop.
  const double motion_t = std::max(0.0, t - hold_s_);
  HandFrame f;
  if (pose_set_) {
    const auto& frames = pose_set_->frames;
    const double pos = motion_t * config_.pose_set_rate_hz;
    const auto n = static_cast<std::int64_t>(frames.size());
    const auto i0 = static_cast<std::int64_t>(std::floor(pos));
    const double frac = pos - std::floor(pos);
    const HandFrame& a = frames[static_cast<size_t>(((i0 % n) + n) % n)];
    const HandFrame& b = frames[static_cast<size_t>((((i0 + 1) % n) + n) % n)];
    for (int p = 0; p < kNumHandPoints; ++p) f.point(p) = (1 - frac) * a.point(p) + frac * b.point(p);
    for (int p : {kPalmNormal, kPalmDirection})
      if (f.point(p).norm() > 1e-12) f.point(p).normalize();
  } else {
    const double progress =
        config_.motion == HandMotion::kOpen ? 0.0 : 0.5 * (1.0 - std::cos(kTwoPi * motion_t / config_.motion_period_s));
    HandPlacement placement = placement_;
    const double s = config_.sway_mm;
    placement.wrist_mm +=
        Vec3(s * std::sin(kTwoPi * 0.23 * t + sway_phase_[0]), 0.5 * s * std::sin(kTwoPi * 0.17 * t + sway_phase_[1]),
             s * std::sin(kTwoPi * 0.31 * t + sway_phase_[2]));
    f = model_.pose(motion_angles(config_.motion, progress), placement);
  }
  f.hand_present = true;
  marker_map_->make_consistent(f);
  return f;
}

HandFrame SimRig::device_frame(Device& d, double t) {
  HandFrame out;
  out.points.fill(Vec3::Zero());
  out.device_id = d.index + 1;
  out.frame_id = d.frame_id++;
  out.timestamp_us = config_.device_clock_start_us + static_cast<std::int64_t>(std::llround(t * 1e6));
  if (d.last_time_s >= 0) {
    const double inst = 1.0 / std::max(1e-6, t - d.last_time_s);
    d.reported_rate_hz = d.reported_rate_hz == 0 ? inst : 0.8 * d.reported_rate_hz + 0.2 * inst;
  }
  out.frame_rate_hz = d.reported_rate_hz;  // 0 on the first frame, as the service reports
  d.last_time_s = t;

  const HandFrame truth = truth_at(t);
  bool present = true;
  std::array<bool, kNumDigits> hidden{};
  VisibilityExplanation why;
  if (config_.fov_test || config_.occlusion) {
    why = explain_visibility(prepare_frame(truth), d.view, visibility_[static_cast<size_t>(d.index)]);
  }
  for (int dg = 0; dg < kNumDigits && (config_.fov_test || config_.occlusion); ++dg) {
    const HiddenReason r = why.fingers[static_cast<size_t>(dg)].reason;
    if (r == HiddenReason::kNoHand || r == HiddenReason::kWrongApproach || r == HiddenReason::kOutOfRange ||
        r == HiddenReason::kOutOfView)
      present = present && !config_.fov_test;
    if (r == HiddenReason::kBehindPalm || r == HiddenReason::kBehindFinger) hidden[static_cast<size_t>(dg)] = true;
  }
  if (!present) return out;

  HandFrame world = truth;
  if (!config_.occlusion) {
    // Nothing to remember: every finger is reported as it is.
  } else if (auto basis = palm_basis(truth)) {
    for (int dg = 0; dg < kNumDigits; ++dg) {
      auto& seen = d.last_seen_local[static_cast<size_t>(dg)];
      if (!hidden[static_cast<size_t>(dg)]) {
        for (int j = 0; j < kJointsPerDigit; ++j)
          seen[static_cast<size_t>(j)] = basis->axes.transpose() * (truth.point(digit_point(dg, j)) - basis->origin);
        d.seen[static_cast<size_t>(dg)] = true;
        continue;
      }
      // The service's internal model fills the unseen finger: where it last saw it (lagging),
      // drawn towards its default open finger (biased), carried along by the palm.
      const double b = d.seen[static_cast<size_t>(dg)] ? config_.internal_model_bias : 1.0;
      for (int j = 0; j < kJointsPerDigit; ++j) {
        const Vec3 local = (1 - b) * seen[static_cast<size_t>(j)] +
                           b * neutral_local_[static_cast<size_t>(dg)][static_cast<size_t>(j)];
        world.point(digit_point(dg, j)) = basis->origin + basis->axes * local;
      }
    }
  }

  if (d.hand_model) apply_controller_hand_model(*d.hand_model, world);

  // Unit draws scaled by the device's σ: the same draws as N(0, σ) gives (y·σ + 0), bit for bit,
  // for every σ, and σ = 0 (which the distribution itself does not allow) still draws, so the
  // device's stream and everything drawn after the noise stay where they were.
  std::normal_distribution<double> noise(0.0, 1.0);
  const Eigen::Matrix3d rt = d.r.transpose();
  out.hand_present = true;
  for (int p = 0; p < kNumHandPoints; ++p) {
    if (p == kPalmNormal || p == kPalmDirection) {
      out.point(p) = rt * world.point(p);
      continue;
    }
    Vec3 q = rt * (world.point(p) - d.origin);
    if (p == kElbow) q += d.elbow_error;
    if (config_.noise) q += d.noise_sigma_mm * Vec3(noise(d.rng), noise(d.rng), noise(d.rng));
    if (config_.axis_cut)
      for (int k = 0; k < 3; ++k) q[k] = std::clamp(q[k], -config_.axis_cut_mm, config_.axis_cut_mm);
    out.point(p) = q;
  }
  return out;
}

SimEvent SimRig::next() {
  SimEvent ev;
  if (announced_ < devices_.size()) {
    const Device& d = *devices_[announced_++];
    ev.time_s = 0;
    ev.is_frame = false;
    ev.event.kind = DeviceEventKind::kAppeared;
    ev.event.info = d.info;
    return ev;
  }
  for (;;) {
    Device* d = devices_.front().get();
    for (auto& o : devices_)
      if (o->next_time_s < d->next_time_s) d = o.get();
    const double t = d->next_time_s;
    // Unplug windows: announce the loss at its start, skip frames inside, announce the return.
    bool in_window = false;
    for (const auto& u : d->unplugs)
      if (t >= hold_s_ + u.at_s && (u.duration_s < 0 || t < hold_s_ + u.at_s + u.duration_s)) in_window = true;
    if (in_window && d->connected) {
      d->connected = false;
      ev.time_s = t;
      ev.is_frame = false;
      ev.event.kind = DeviceEventKind::kLost;
      ev.event.info = d->info;
      ev.event.message = "simulated unplug";
      return ev;
    }
    if (!in_window && !d->connected) {
      d->connected = true;
      ev.time_s = t;
      ev.is_frame = false;
      ev.event.kind = DeviceEventKind::kAppeared;
      ev.event.info = d->info;
      ev.event.message = "simulated re-plug";
      return ev;
    }
    // Next frame time: the device's rate wanders inside [min, max] (shared-bus variability).
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double lo = config_.rate_min_hz * d->rate_scale, hi = config_.rate_max_hz * d->rate_scale;
    d->rate_hz = std::clamp(d->rate_hz + u(d->rng) * config_.rate_wander * (hi - lo), lo, hi);
    d->next_time_s = t + 1.0 / d->rate_hz;
    if (in_window) continue;
    ev.time_s = t;
    ev.is_frame = true;
    ev.frame.serial = d->info.serial;
    ev.frame.frame = device_frame(*d, t);
    std::uniform_real_distribution<double> latency(config_.latency_min_ms, config_.latency_max_ms);
    ev.frame.host_receive_ns = static_cast<std::int64_t>(std::llround((t + latency(d->rng) / 1000.0) * 1e9));
    ev.frame.hand_type = HandType::kRight;
    ev.frame.confidence = 1.0F;
    return ev;
  }
}

std::vector<std::pair<std::string, std::int64_t>> SimTrial::frame_counts() const {
  std::map<std::string, std::int64_t> counts;
  for (const auto& d : devices) counts[d.serial] = 0;
  for (const auto& e : events)
    if (e.is_frame) ++counts[e.frame.serial];
  return {counts.begin(), counts.end()};
}

SimTrial generate_sim_trial(const Layout& layout, const SimConfig& config, double seconds) {
  SimRig rig(layout, config);
  SimTrial trial;
  trial.devices = rig.devices();
  trial.truth_rate_hz = config.truth_rate_hz;
  for (;;) {
    SimEvent e = rig.next();
    if (e.time_s >= seconds) break;
    trial.events.push_back(std::move(e));
  }
  const auto n = static_cast<int>(std::floor(seconds * config.truth_rate_hz + 1e-9));
  trial.truth.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) trial.truth.push_back(rig.truth_at(i / config.truth_rate_hz));
  trial.truth_trc = truth_trc(trial.truth, config.truth_rate_hz, rig.marker_map());
  return trial;
}

}  // namespace lmc::devices
