#include "core/hand/pose_set_generator.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "core/common/error.h"

namespace lmc {
namespace {

// Uniform [0, 1) and standard normal draws written out here (not std::*_distribution, whose
// algorithms differ between standard libraries) so a seed means the same pose set everywhere.
struct Rng {
  std::mt19937_64 engine;
  explicit Rng(std::uint64_t seed) : engine(seed) {}
  double uniform() { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }
  double normal() {
    // Box–Muller, one value per call (the second is dropped to keep the sequence simple).
    double u1 = uniform();
    while (u1 <= 0.0) u1 = uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  int below(int n) { return static_cast<int>(uniform() * n); }
};

}  // namespace

PoseSet generate_pose_set(const HandModel& model, const PoseSetSettings& s) {
  if (s.frames < 0 || s.frames > 10'000'000) throw Error("pose set size must be 0…10000000 frames");
  if (!(s.joint_noise_deg >= 0) || !(s.position_jitter_mm >= 0) || !(s.orientation_jitter_deg >= 0)) {
    throw Error("pose set noise levels must be non-negative");
  }
  PoseSet set;
  set.description = "monte-carlo seed=" + std::to_string(s.seed) + " frames=" + std::to_string(s.frames);
  set.frames.reserve(static_cast<size_t>(s.frames));
  set.labels.reserve(static_cast<size_t>(s.frames));
  Rng rng(s.seed);
  const double deg = std::numbers::pi / 180.0;
  for (int i = 0; i < s.frames; ++i) {
    PoseLabel label;
    label.orientation = static_cast<HandOrientation>(rng.below(kNumHandOrientations));
    label.motion = static_cast<HandMotion>(rng.below(kNumHandMotions));
    const double u = rng.uniform();
    label.progress = label.motion == HandMotion::kOpen ? 0.0 : u;
    HandJointAngles angles = motion_angles(label.motion, label.progress);
    for (int k = 0; k < kNumHandJointParams; ++k) {
      set_joint_param(angles, k, joint_param(angles, k) + s.joint_noise_deg * rng.normal());
    }
    // Base placement, then a small rotation about the palm centre and a translation.
    HandPlacement pl;
    if (label.orientation == HandOrientation::kVertical) {
      pl.rotation = Eigen::AngleAxisd(-std::numbers::pi / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    }
    Eigen::Vector3d rv(rng.normal(), rng.normal(), rng.normal());
    rv *= s.orientation_jitter_deg * deg;
    const double angle = rv.norm();
    const Eigen::Matrix3d jitter =
        angle > 0 ? Eigen::AngleAxisd(angle, rv / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
    pl.rotation = jitter * pl.rotation;
    const Eigen::Vector3d shift(rng.normal(), rng.normal(), rng.normal());
    const Eigen::Vector3d palm_target = Eigen::Vector3d(0.0, s.palm_height_mm, 0.0) + s.position_jitter_mm * shift;
    // The palm centre lands on the (jittered) target even when the wrist bends (reference_poses.h).
    pl.wrist_mm = palm_target - pl.rotation * model.palm_position(angles);
    set.frames.push_back(model.pose(angles, pl));
    set.frames.back().frame_id = i;
    set.labels.push_back(label);
  }
  return set;
}

}  // namespace lmc
