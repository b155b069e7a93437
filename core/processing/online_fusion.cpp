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
    s.hand = false;
    s.z.fill(kNaN);
    s.var.fill(kNaN);
  }
  kf_.fill(CvKalman{});
  prior_.fill(CvKalman{});
  state_t_.fill(0.0);
  meas_t_.fill(0.0);
  live_.fill(false);
  started_.fill(false);
  latest_s_ = 0.0;
  any_frame_ = false;
}

bool OnlineFusion::combine(int lane, double t, double& z, double& r) const {
  double wsum = 0.0, zsum = 0.0;
  for (const Slot& s : slots_) {
    const double y = s.z[static_cast<size_t>(lane)];
    if (!s.hand || !std::isfinite(y)) continue;
    const double age = t > s.t_s ? t - s.t_s : 0.0;
    if (age > kStaleAfterS + kTimeEpsS) continue;
    // An older sample says less about now: the model's process noise over `age` widens it. It is
    // not carried forward with the filter's velocity: a measurement that depends on the state
    // feeds the velocity back into itself and diverged on the recorded trial. At age 0 this is
    // exactly the offline combination.
    const double var = s.var[static_cast<size_t>(lane)] + params_.accel_psd * age * age * age / 3.0;
    wsum += 1.0 / var;
    zsum += y / var;
  }
  if (!(wsum > 0.0)) return false;
  z = zsum / wsum;
  r = 1.0 / wsum;
  return true;
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
  // A frame older than the slot's latest (crossed in delivery) must not replace newer data.
  if (slot.ever && t_s < slot.t_s) return;
  const bool hand = frame.hand_present && is_finite(frame.point(kPalm));

  // 1. Ray tracing in the device's own frame, exactly as visibility_labels does for a track.
  if (hand) {
    const PreparedFrame prepared = prepare_frame(frame);
    slot.labels = frame_visibility_labels(prepared, true, limits_);
  } else {
    static const PreparedFrame kNoHand{};  // nothing to prepare: the rule gives the "no hand" row
    slot.labels = frame_visibility_labels(kNoHand, false, limits_);
  }
  slot.t_s = t_s;
  slot.ever = true;
  slot.hand = hand;
  if (!hand) return;

  // 2. Variance factors before realignment (axis cuts are device-frame coordinates).
  std::array<float, kNumHandPoints> quality;
  frame_quality(frame.points, &slot.labels, params_, quality);

  // 3. Into the world frame; the slot keeps it as its latest sample.
  std::array<Vec3, kNumHandPoints> world = frame.points;
  realign_frame(world, slot.rotation, slot.shift);
  hand_to_lanes(world, quality, base_var_, slot.z, slot.var);

  // 4. Lanes this frame measured: predict to t_s (a new instant) or redo the update at the
  // current one, with every device's latest sample.
  const double restart_gap_s = max_gap_s_ + params_.dt_s + kTimeEpsS;
  for (int lane = 0; lane < kLanes; ++lane) {
    const auto l = static_cast<size_t>(lane);
    if (!std::isfinite(slot.z[l])) continue;
    const bool restart = !live_[l] || t_s - meas_t_[l] > restart_gap_s;
    if (t_s > meas_t_[l] || !live_[l]) meas_t_[l] = t_s;
    double z = 0.0, r = 0.0;
    if (restart || (started_[l] && t_s <= state_t_[l])) {
      // A (re)start at rest from the devices' combination at this instant: redone, not updated,
      // when the next device of the same instant arrives, as the offline fuser starts from the
      // combined first step.
      if (restart) state_t_[l] = t_s;
      if (!combine(lane, state_t_[l], z, r)) continue;
      kf_[l].start(z, r);
      prior_[l] = kf_[l];
      live_[l] = true;
      started_[l] = true;
      continue;
    }
    if (t_s > state_t_[l]) {
      prior_[l] = kf_[l];
      prior_[l].predict(t_s - state_t_[l], params_.accel_psd);
      state_t_[l] = t_s;
      started_[l] = false;
    }
    CvKalman next = prior_[l];
    if (combine(lane, state_t_[l], z, r)) next.update(z, r);
    kf_[l] = next;
  }
}

FusedHand OnlineFusion::current() const {
  return current_at(latest_s_);
}

FusedHand OnlineFusion::current_at(double t_s) const {
  FusedHand out;
  out.t_s = t_s;
  std::array<double, kLanes> lanes;
  for (int lane = 0; lane < kLanes; ++lane) {
    const auto l = static_cast<size_t>(lane);
    double v = kNaN;
    if (live_[l] && t_s - meas_t_[l] <= max_gap_s_ + kTimeEpsS) {
      const double ahead = t_s > state_t_[l] ? t_s - state_t_[l] : 0.0;
      v = kf_[l].x0 + ahead * kf_[l].x1;
    }
    lanes[l] = v;
  }
  lanes_to_hand(lanes, out.points);
  for (const Slot& s : slots_) {
    if (!s.ever || t_s - s.t_s > kStaleAfterS + kTimeEpsS) continue;
    for (int k = 0; k < kNumDigits; ++k)
      out.seen_by[static_cast<size_t>(k)] += s.labels[static_cast<size_t>(k)] == 1 ? 1 : 0;
  }
  out.has_hand = is_finite(out.points[kPalm]);
  return out;
}

}  // namespace lmc
