#include "core/calibration/rigid_transform.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace lmc::calibration {

RigidTransform device_transform(const LayoutDevice& device) {
  return {device.pose.rotation(), device.pose.translation() + device.offset_mm};
}

double rotation_angle_deg(const Eigen::Matrix3d& r) {
  // atan2(sin, cos) stays accurate for tiny angles, where acos of the trace loses digits.
  const Vec3 axis_sin(r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1));
  return std::atan2(0.5 * axis_sin.norm(), (r.trace() - 1.0) / 2.0) * 180.0 / std::numbers::pi;
}

Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& m) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

RigidTransform weighted_kabsch(std::span<const Vec3> src, std::span<const Vec3> dst, std::span<const double> weights) {
  double wsum = 0;
  Vec3 cs = Vec3::Zero(), cd = Vec3::Zero();
  for (size_t i = 0; i < src.size(); ++i) {
    wsum += weights[i];
    cs += weights[i] * src[i];
    cd += weights[i] * dst[i];
  }
  RigidTransform out;
  if (wsum <= 0) return out;
  cs /= wsum;
  cd /= wsum;
  // Cross-covariance H = Σ w·(dst − cd)(src − cs)ᵀ; R = the rotation nearest to H.
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < src.size(); ++i) h += weights[i] * (dst[i] - cd) * (src[i] - cs).transpose();
  out.r = nearest_rotation(h);
  out.t = cd - out.r * cs;
  return out;
}

void huber_weights(std::span<const double> residuals, const RobustFitOptions& options, std::vector<double>& weights) {
  weights.assign(residuals.size(), 1.0);
  if (residuals.empty()) return;
  std::vector<double> sorted(residuals.begin(), residuals.end());
  const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), mid, sorted.end());
  const double k = std::max(options.min_threshold_mm, options.threshold_sigmas * 1.4826 * *mid);
  for (size_t i = 0; i < residuals.size(); ++i) weights[i] = residuals[i] <= k ? 1.0 : k / residuals[i];
}

RigidTransform robust_rigid_fit(std::span<const Vec3> src, std::span<const Vec3> dst, const RigidTransform& start,
                                const RobustFitOptions& options, std::vector<double>* weights_out) {
  RigidTransform current = start;
  std::vector<double> residuals(src.size()), weights;
  for (int it = 0; it < options.max_iterations; ++it) {
    for (size_t i = 0; i < src.size(); ++i) residuals[i] = (current.apply(src[i]) - dst[i]).norm();
    huber_weights(residuals, options, weights);
    const RigidTransform next = weighted_kabsch(src, dst, weights);
    double moved = 0;
    for (size_t i = 0; i < src.size(); i += std::max<size_t>(1, src.size() / 64))
      moved = std::max(moved, (next.apply(src[i]) - current.apply(src[i])).norm());
    current = next;
    if (moved < options.tolerance_mm) break;
  }
  if (weights_out != nullptr) {
    for (size_t i = 0; i < src.size(); ++i) residuals[i] = (current.apply(src[i]) - dst[i]).norm();
    huber_weights(residuals, options, *weights_out);
  }
  return current;
}

}  // namespace lmc::calibration
