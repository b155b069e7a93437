#pragma once
// Our **default** fusion (stage 4): per lane, a constant-velocity Kalman filter (white-noise
// acceleration) run forward and then smoothed backward (Rauch–Tung–Striebel), so the fused
// trajectory has no filter lag. The lanes (fusion_lanes.h) are the points' coordinates and, as
// quantities of their own, the finger bones' lengths: the fused hand is rebuilt with the fused
// lengths so that controllers whose realigned hands disagree cannot shorten it. At each step the
// devices that have a value are combined by inverse-variance weighting, where a device's variance
// is a base noise times a *quality factor* computed before realignment:
//  * the ray tracer (visibility_labels.h) says the device could not see this finger: its value is
//    the controller's internal-model guess, so its variance is multiplied by `hidden_factor`;
//  * a device-frame coordinate sits at the controller's axis cut (within the margin of
//    ±axis_cut_mm, the "250 mm" clipping in the paper's Discussion): multiplied by
//    `axis_cut_factor` — for a finger joint, the whole finger, so one finger's joints are never
//    weighted differently;
//  * the elbow (the study found it systematically wrong) gets `elbow_factor`.
// Frames where no device has had a value for more than `max_gap_frames` stay NaN (the reference
// filter would coast on its last velocity there). NaN from any device at any time is skipped.
#include <span>
#include <vector>

#include "core/hand/hand_track.h"
#include "core/io/lmc_recording.h"

namespace lmc {

// Which computation fuse_default does for the same parameters. It is part of the processing cache's
// key and of every export's parameters (process_options_json.h), so a result fused by an older
// rule is never reused or mistaken for a current one. 2: bone-length lanes, one cut weight per
// finger, cut only at the cut value.
inline constexpr int kDefaultFusionRevision = 2;

struct SmootherParams {
  double dt_s = 0.01;
  double accel_psd = 2.0e5;      // mm²/s³: white-noise acceleration spectral density (points and bone lengths)
  double noise_mm = 1.5;         // base measurement standard deviation of a visible point
  double hidden_factor = 400.0;  // variance × this for an internal-model guess (σ × 20)
  double axis_cut_factor = 400.0;
  double axis_cut_mm = 250.0;
  double axis_cut_margin_mm = 0.5;  // |coordinate| within this of axis_cut_mm counts as cut
  double elbow_factor = 25.0;
  int max_gap_frames = 5;  // 50 ms at 100 Hz, as the resampler's gap limit
};

// Per device: variance factor per (frame, point), frame-major like HandTrack; all joints of a
// finger share one factor. `device_frame` is the device's track before realignment; `labels` its
// visibility labels (may be empty: all visible).
std::vector<float> sample_quality(const HandTrack& device_frame, const std::vector<FingerLabels>& labels,
                                  const SmootherParams& params = {});

// The per-frame rule of sample_quality, shared with the online fuser (online_fusion.h) so live and
// offline weights cannot drift apart: one frame's 30 device-frame entries and its labels (null:
// all visible) → 30 variance factors.
void frame_quality(std::span<const Vec3, kNumHandPoints> device_points, const FingerLabels* labels,
                   const SmootherParams& params, std::span<float, kNumHandPoints> out);

// Fuses realigned tracks. `quality[d]` may be null (factor 1 everywhere).
HandTrack fuse_default(const std::vector<const HandTrack*>& devices,
                       const std::vector<const std::vector<float>*>& quality, const SmootherParams& params = {});

}  // namespace lmc
