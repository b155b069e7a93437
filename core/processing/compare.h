#pragma once
// Stage 6 (docs/algorithms/processing.md): LMC against Vicon. Both series start on the same
// trigger at 100 Hz, so the study trimmed both to the shorter one; we do the same and, in
// addition, estimate any residual lag by cross-correlating the wrist trajectories (reported, not
// applied, so reference numbers stay comparable). Differences are LMC − Vicon.
#include <array>
#include <vector>

#include "core/processing/measures.h"

namespace lmc {

struct LagEstimate {
  bool valid = false;      // false when too few common frames or a flat trajectory
  int lag_frames = 0;      // > 0: LMC trails Vicon (lmc[f] ≈ vicon[f − lag])
  double correlation = 0;  // normalised cross-correlation at that lag (1 = identical shape)
  // valid, r ≥ 0.9 and inside the search window (a best lag at ±max_lag means the true one may lie
  // beyond it): a lag worth reporting to a person. Low-motion trials rarely give one.
  bool clear = false;
};

// Normalised cross-correlation of the demeaned wrist (point 4) trajectories over lags
// −max_lag…max_lag frames; requires at least half of the frames to overlap.
LagEstimate estimate_lag(const HandTrack& lmc, const HandTrack& vicon, int max_lag_frames = 50);

struct Comparison {
  int frames = 0;  // common frames compared
  LagEstimate lag;
  // Per frame LMC − Vicon, then mean and SD over frames (NaN skipped).
  std::array<double, kNumFingers> finger_diff_mean{}, finger_diff_sd{};
  std::array<double, kNumAngles> angle_diff_mean{}, angle_diff_sd{};
  // Trial-level: mean finger length LMC − Vicon; range of motion LMC − Vicon.
  std::array<double, kNumFingers> finger_mean_diff{};
  std::array<double, kNumAngles> rom_diff{};
};

Comparison compare_measures(const std::vector<FrameMeasures>& lmc, const MeasureStats& lmc_stats,
                            const std::vector<FrameMeasures>& vicon, const MeasureStats& vicon_stats);

}  // namespace lmc
