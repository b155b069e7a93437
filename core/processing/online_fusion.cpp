#include "core/processing/online_fusion.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

#include "core/common/error.h"
#include "core/processing/realign.h"
#include "core/visibility/frame_prep.h"

namespace lmc {
namespace {

// Slack for comparing times computed from timestamps (µs → s rounding).
constexpr double kTimeEpsS = 1e-9;

}  // namespace

OnlineFusion::OnlineFusion(const Layout& layout, SmootherParams params, VisibilityParams vis)
    : params_(params), limits_(make_limits(vis)) {
  if (const std::string problem = validate_layout(layout); !problem.empty()) {
    throw Error("online fusion: invalid layout '" + layout.name + "': " + problem);
  }
  if (!(params.dt_s > 0.0) || !(params.noise_mm > 0.0) || !(params.accel_psd >= 0.0) || params.max_gap_frames < 0) {
    throw Error("online fusion: dt_s and noise_mm must be positive, accel_psd and max_gap_frames not negative");
  }
  base_var_ = params.noise_mm * params.noise_mm;
  max_gap_s_ = params.max_gap_frames * params.dt_s;
  slots_.resize(layout.devices.size());
  for (size_t d = 0; d < layout.devices.size(); ++d) {
    const LayoutDevice& dev = layout.devices[d];
    slots_[d].rotation = dev.pose.rotation();
    slots_[d].shift = dev.pose.translation() + dev.offset_mm;
  }
  reset();
}

void OnlineFusion::reset() {
  for (Slot& s : slots_) {
    s.labels.fill(-1);
    s.t_s = 0.0;
    s.ever = false;
  }
  kf_.fill(CvKalman{});
  state_t_.fill(0.0);
  meas_t_.fill(0.0);
  live_.fill(false);
  latest_s_ = 0.0;
  any_frame_ = false;
}

void OnlineFusion::add(const HandFrame& frame, int slot_index, double t_s) {
  if (slot_index < 0 || slot_index >= slot_count()) {
    throw Error("online fusion: slot " + std::to_string(slot_index) + " is out of range (the layout has " +
                std::to_string(slot_count()) + " device(s))");
  }
  if (!std::isfinite(t_s)) throw Error("online fusion: frame time is not finite");
  latest_s_ = any_frame_ ? std::max(latest_s_, t_s) : t_s;
  any_frame_ = true;

  Slot& slot = slots_[static_cast<size_t>(slot_index)];
  // A frame older than the slot's latest (crossed in delivery) must not replace newer labels.
  const bool newest_for_slot = !slot.ever || t_s >= slot.t_s;
  const bool hand = frame.hand_present && is_finite(frame.point(kPalm));

  // 1. Ray tracing in the device's own frame, exactly as visibility_labels does for a track.
  FingerLabels labels;
  if (hand) {
    const PreparedFrame prepared = prepare_frame(frame);
    labels = frame_visibility_labels(prepared, true, limits_);
  } else {
    labels = frame_visibility_labels(PreparedFrame{}, false, limits_);
  }
  if (newest_for_slot) {
    slot.labels = labels;
    slot.t_s = t_s;
    slot.ever = true;
  }
  if (!hand) return;

  // 2. Variance factors before realignment (axis cuts are device-frame coordinates).
  std::array<float, kNumHandPoints> quality;
  frame_quality(frame.points, &labels, params_, quality);

  // 3. Into the world frame.
  std::array<Vec3, kNumHandPoints> world = frame.points;
  realign_frame(world, slot.rotation, slot.shift);

  // 4. Predict to t_s and update, lane by lane. A lane unseen for longer than the gap limit (a
  // stretch the offline fuser would leave NaN) restarts at rest from this measurement.
  const double restart_gap_s = max_gap_s_ + params_.dt_s + kTimeEpsS;
  for (int lane = 0; lane < kLanes; ++lane) {
    const int point = lane / 3;
    const double z = world[static_cast<size_t>(point)][lane % 3];
    if (!std::isfinite(z)) continue;
    const double r = base_var_ * static_cast<double>(quality[static_cast<size_t>(point)]);
    const auto l = static_cast<size_t>(lane);
    CvKalman& kf = kf_[l];
    if (!live_[l] || t_s - meas_t_[l] > restart_gap_s) {
      kf.start(z, r);
      state_t_[l] = t_s;
      meas_t_[l] = t_s;
      live_[l] = true;
      continue;
    }
    if (t_s > state_t_[l]) {
      kf.predict(t_s - state_t_[l], params_.accel_psd);
      state_t_[l] = t_s;
    }
    kf.update(z, r);
    if (t_s > meas_t_[l]) meas_t_[l] = t_s;
  }
}

FusedHand OnlineFusion::current() const { return current_at(latest_s_); }

FusedHand OnlineFusion::current_at(double t_s) const {
  FusedHand out;
  out.t_s = t_s;
  for (int lane = 0; lane < kLanes; ++lane) {
    const auto l = static_cast<size_t>(lane);
    double v = kNaN;
    if (live_[l] && t_s - meas_t_[l] <= max_gap_s_ + kTimeEpsS) {
      const double ahead = t_s > state_t_[l] ? t_s - state_t_[l] : 0.0;
      v = kf_[l].x0 + ahead * kf_[l].x1;
    }
    out.points[static_cast<size_t>(lane / 3)][lane % 3] = v;
  }
  for (const Slot& s : slots_) {
    if (!s.ever || t_s - s.t_s > kSeenWindowS + kTimeEpsS) continue;
    for (int k = 0; k < kNumDigits; ++k) out.seen_by[static_cast<size_t>(k)] += s.labels[static_cast<size_t>(k)] == 1 ? 1 : 0;
  }
  out.has_hand = is_finite(out.points[kPalm]);
  return out;
}

}  // namespace lmc
