#pragma once
// The study's fusion, exactly (docs/algorithms/fusion.md — the **reference** method): every one
// of the 90 coordinates separately, a 1-D constant-velocity Kalman filter (dt 0.01 s,
// Q = diag(0.04, 1), P0 = diag(100, 300)), started at the first step where any device (in device
// order) has a value, then per step: predict, and update with each device in order whose value and
// rolling variance are both defined; the measurement variance is the centred rolling sample
// variance of that device's own series (window i−15 … i+14, NaN ignored, ddof 1: pandas'
// rolling(30, center=True, min_periods=1).var()). Output is NaN before the start.
#include <vector>

#include "core/hand/hand_track.h"

namespace lmc {

struct ReferenceKalmanParams {
  double dt_s = 0.01;
  double q_position = 0.04;
  double q_velocity = 1.0;
  double p0_position = 100.0;
  double p0_velocity = 300.0;
  int window = 30;  // rolling-variance window, centred as pandas centres an even window
};

// Centred rolling sample variance with NaN skipped (fewer than two values → NaN).
void rolling_variance(const double* x, int n, int window, double* out);

// One coordinate: series[d] points at device d's n values (NaN = no sample). Writes n outputs.
void kalman_reference_1d(const std::vector<const double*>& series, int n, double* out,
                         const ReferenceKalmanParams& params = {});

// All 30 entries × 3 coordinates of the given device tracks (device order = update order).
HandTrack fuse_reference(const std::vector<const HandTrack*>& devices, const ReferenceKalmanParams& params = {});

}  // namespace lmc
