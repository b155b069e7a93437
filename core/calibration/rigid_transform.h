#pragma once
// A rigid device-to-world transform p_world = r·p_device + t, the quantity calibration refines,
// and the two fits it is built from. Kept apart from DevicePose (Euler angles, for people and
// files) because the fits work on matrices and convert only at the end (calibrated_layout.h).
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "core/hand/hand_frame.h"
#include "core/layout/layout.h"

namespace lmc {

struct RigidTransform {
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  Vec3 t = Vec3::Zero();

  Vec3 apply(const Vec3& p) const { return r * p + t; }
  RigidTransform inverse() const { return {r.transpose(), -(r.transpose() * t)}; }
  // (this ∘ other)(p) = this(other(p)).
  RigidTransform compose(const RigidTransform& other) const { return {r * other.r, r * other.t + t}; }
};

// The transform a layout device applies (pose, then offset: docs/algorithms/frames.md).
RigidTransform device_transform(const LayoutDevice& device);

// Rotation angle of r in degrees (0…180).
double rotation_angle_deg(const Eigen::Matrix3d& r);

// The nearest rotation to a 3×3 matrix (polar factor via SVD, determinant forced to +1).
Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& m);

// Weighted least squares rigid fit (Kabsch): the transform minimising Σ w_i·|T(src_i) − dst_i|².
// All three spans have the same length; the weights sum to more than zero.
RigidTransform weighted_kabsch(std::span<const Vec3> src, std::span<const Vec3> dst, std::span<const double> weights);

// Masked samples: a source point (device frame) of which only some device axes are trusted (bit k:
// axis k), e.g. a point the controller clamped at its axis cut (calibration_samples.h). Its
// residual is taken in the device frame, Tᵀ(dst) − src, over the trusted axes only.
inline constexpr std::uint8_t kAllAxes = 7;
double masked_distance(const RigidTransform& t, const Vec3& src, const Vec3& dst, std::uint8_t axes);
// The transform minimising Σ w_i·Σ_{k trusted} (Tᵀ(dst_i) − src_i)_k², by Gauss–Newton from
// `start` (no closed form once axes are missing). With every axis trusted it has Kabsch's minimum.
RigidTransform weighted_masked_fit(std::span<const Vec3> src, std::span<const Vec3> dst,
                                   std::span<const std::uint8_t> axes, std::span<const double> weights,
                                   const RigidTransform& start);

struct RobustFitOptions {
  int max_iterations = 30;
  // Huber threshold k = max(min_threshold_mm, threshold_sigmas · σ̂), σ̂ = 1.4826 · median residual:
  // residuals below k count fully, larger ones with weight k/r, so a few grossly wrong samples
  // (a finger the ray tracer let through, a Vicon marker swap) pull linearly, not quadratically.
  double min_threshold_mm = 2.0;
  double threshold_sigmas = 1.345;
  double tolerance_mm = 1e-4;  // stop when no point moves further between iterations
};

// Huber-weighted iteratively reweighted Kabsch from `start`. `weights_out` (optional) gets the
// final weights. Deterministic: no randomness, no threads. With `axes` (one per sample) and some
// sample not whole, each step is the masked fit instead of Kabsch.
RigidTransform robust_rigid_fit(std::span<const Vec3> src, std::span<const Vec3> dst, const RigidTransform& start,
                                const RobustFitOptions& options, std::vector<double>* weights_out = nullptr,
                                std::span<const std::uint8_t> axes = {});

// Whether any of `axes` leaves an axis out.
bool any_masked(std::span<const std::uint8_t> axes);

// The Huber weights of residuals (mm) under `options` (shared by both fits).
void huber_weights(std::span<const double> residuals, const RobustFitOptions& options, std::vector<double>& weights);

}  // namespace lmc
