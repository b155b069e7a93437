#pragma once
// Monte Carlo pose sets (the paper's "Monte Carlo simulation of hand trajectories expected in
// trials"): each sample picks an orientation and a trial motion uniformly, a progress along the
// motion (uniform in [0, 1]), then adds per-joint noise and jitters the hand's position and
// orientation. The palm centre is placed palm_height_mm above the table centre (plus jitter) in
// every pose, the wrist bending around it as in reference_poses.h. Deterministic for a seed (std::mt19937_64 and our
// own normal/uniform draws, so the numbers do not depend on the standard library's distribution implementations).
#include <cstdint>

#include "core/hand/hand_model.h"
#include "core/hand/pose_set.h"

namespace lmc {

struct PoseSetSettings {
  int frames = 10000;
  std::uint64_t seed = 1;
  double joint_noise_deg = 5.0;         // σ of the per-joint normal noise
  double position_jitter_mm = 15.0;     // σ per axis of the hand position
  double orientation_jitter_deg = 5.0;  // σ per axis of a small rotation about the palm centre
  double palm_height_mm = kReferencePalmHeight_mm;
};

PoseSet generate_pose_set(const HandModel& model, const PoseSetSettings& settings);

}  // namespace lmc
