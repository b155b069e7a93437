#pragma once
// The default fusion (fusion_smoother.h), causal: one device frame at a time as it arrives, for
// the live fused hand of the Record and Devices tabs. Per frame it does what the
// offline stages do for a whole trial, with the same code:
//  1. ray-traces the frame in the device's own frame (visibility_labels.h, frame_visibility_labels);
//  2. turns labels and axis cuts into variance factors (fusion_smoother.h, frame_quality);
//  3. realigns the points with the slot's pose and offset (realign.h, realign_frame);
//  4. turns the points into the fusion's lanes (fusion_lanes.h: point coordinates and bone
//     lengths) and, per lane, predicts the constant-velocity Kalman filter (cv_kalman.h) to the
//     frame's time and updates it with the inverse-variance combination of every device's latest
//     sample, as the offline fuser combines the devices at each grid step; current() rebuilds the
//     hand from the lanes as the offline fuser does.
// Why combine the latest samples instead of updating with the arriving device alone: controllers
// disagree by several millimetres (calibration, internal-model guesses) and stream at different
// rates; updated one device at a time, the responsive filter would jump towards each arriving
// device in turn (millimetres of jitter a viewer sees; core/processing/README.md). A held sample's variance grows with
// its age by the model's process noise (it is not moved with the filter's velocity: that feedback diverged); it stops
// counting kStaleAfterS after its device's latest frame, or at once when the device reports no hand. Every update
// happens at one instant per point: a second frame at the same time (the next device of the same tracking event) redoes
// that instant's update with the new combination, so four devices on one grid time give exactly the offline forward
// filter. Differences from the offline result, on purpose: no backward (RTS) pass, so the output lags a moving hand
// slightly (tests report how much); a frame older than a point's state joins the update at the state's time instead of
// rewinding it; a point unseen by every device for longer than max_gap_frames·dt_s is NaN, and restarts at rest from
// its next measurement (the velocity from before a long gap is stale). add() and current() never allocate; one
// OnlineFusion is not thread-safe (the tab owns one on its worker thread and publishes FusedHand copies).
#include <array>
#include <cstdint>
#include <vector>

#include "core/hand/hand_frame.h"
#include "core/layout/layout.h"
#include "core/processing/cv_kalman.h"
#include "core/processing/fusion_lanes.h"
#include "core/processing/fusion_smoother.h"
#include "core/processing/visibility_labels.h"

namespace lmc {

struct FusedHand {
  double t_s = 0.0;                           // the time the points are predicted to (shared device clock)
  std::array<Vec3, kNumHandPoints> points{};  // world frame; NaN where no device saw the point recently
  // Per finger (thumb … pinky): how many controllers' latest frames, no older than
  // OnlineFusion::kStaleAfterS, see it by the ray tracer.
  std::array<int, kNumDigits> seen_by{};
  bool has_hand = false;  // the fused palm position is finite
};

class OnlineFusion {
 public:
  // A device's latest frame counts (for seen_by and in the combination) while at most this old.
  static constexpr double kStaleAfterS = 0.1;

  // Throws lmc::Error when the layout is invalid (validate_layout) or params are not positive.
  explicit OnlineFusion(const Layout& layout, SmootherParams params = {},
                        VisibilityParams vis = recorded_trial_visibility_params());

  // One device frame in device coordinates from layout.devices[slot_index], at t_s seconds on the
  // clock all devices share. A frame without a hand (or with a non-finite palm) sets that
  // device's labels to −1 and withdraws its samples; non-finite coordinates are skipped; a frame
  // older than the slot's latest (crossed in delivery) is ignored. Throws lmc::Error for a slot
  // out of range or a non-finite time.
  void add(const HandFrame& device_frame, int slot_index, double t_s);

  // The fused hand predicted to the latest time added (current_at(latest_time_s())).
  FusedHand current() const;
  // The fused hand predicted to `t_s` (e.g. "now" on the shared clock, so a hand whose devices
  // all stopped sending fades to NaN after the gap limit). t_s earlier than a point's state is
  // not rewound.
  FusedHand current_at(double t_s) const;

  double latest_time_s() const { return latest_s_; }
  // The latest labels of a slot (−1 everywhere before its first frame).
  const FingerLabels& slot_labels(int slot_index) const { return slots_[static_cast<size_t>(slot_index)].labels; }
  int slot_count() const { return static_cast<int>(slots_.size()); }
  // Forgets every filter and label (a new trial).
  void reset();

 private:
  static constexpr int kLanes = kFusionLanes;  // fusion_lanes.h

  struct Slot {
    Eigen::Matrix3d rotation;
    Eigen::Vector3d shift;
    FingerLabels labels{};
    double t_s = 0.0;
    bool ever = false;
    bool hand = false;                 // the latest frame had a hand: its samples count
    std::array<double, kLanes> z{};    // latest world-frame sample per lane (NaN: none)
    std::array<double, kLanes> var{};  // its variance per lane (fusion_lanes.h)
  };

  // The inverse-variance combination at time t of every slot's fresh sample of `lane`, each
  // widened by its age. False when no slot has one.
  bool combine(int lane, double t, double& z, double& r) const;

  SmootherParams params_;
  VisibilityLimits limits_{};
  double base_var_ = 0.0;
  double max_gap_s_ = 0.0;
  std::vector<Slot> slots_;  // sized once, in the constructor
  double latest_s_ = 0.0;
  bool any_frame_ = false;

  // Filter state per lane (structure of arrays: the update loop walks them in order).
  std::array<CvKalman, kLanes> kf_{};     // after the update at state_t_
  std::array<CvKalman, kLanes> prior_{};  // predicted to state_t_, before its update (for redoing it)
  std::array<double, kLanes> state_t_{};  // the instant of the lane's latest update
  std::array<double, kLanes> meas_t_{};   // time of the lane's latest measurement from any device
  std::array<bool, kLanes> live_{};       // false: never measured or lost (restart at the next one)
  std::array<bool, kLanes> started_{};    // the update at state_t_ was a (re)start
};

}  // namespace lmc
