#include "core/calibration/rigid_transform.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace lmc {

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

double masked_distance(const RigidTransform& t, const Vec3& src, const Vec3& dst, std::uint8_t axes) {
  if (axes == kAllAxes) return (t.apply(src) - dst).norm();
  const Vec3 d = t.r.transpose() * (dst - t.t) - src;
  double sum = 0;
  for (int k = 0; k < 3; ++k)
    if ((axes >> k) & 1U) sum += d[k] * d[k];
  return std::sqrt(sum);
}

bool any_masked(std::span<const std::uint8_t> axes) {
  for (const auto a : axes)
    if (a != kAllAxes) return true;
  return false;
}

RigidTransform weighted_masked_fit(std::span<const Vec3> src, std::span<const Vec3> dst,
                                   std::span<const std::uint8_t> axes, std::span<const double> weights,
                                   const RigidTransform& start) {
  // Residual of trusted axis k of sample i: c = a_k·(dst − t) − src_k with a_k = r·e_k. A step
  // turns by ω about the targets' weighted centre m and shifts by s (r' = exp([ω]×)·r,
  // t' = m + exp([ω]×)·(t − m) + s), so dc/dω = a_k × (dst − m), dc/ds = −a_k: about the centre,
  // turning and shifting stay well apart in the normal equations.
  RigidTransform current = start;
  double wsum = 0;
  Vec3 centre = Vec3::Zero();
  for (size_t i = 0; i < src.size(); ++i) {
    wsum += weights[i];
    centre += weights[i] * dst[i];
  }
  if (wsum <= 0) return current;
  centre /= wsum;
  for (int it = 0; it < 50; ++it) {
    Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
    for (size_t i = 0; i < src.size(); ++i) {
      if (weights[i] <= 0) continue;
      const Vec3 rel = dst[i] - current.t;
      for (int k = 0; k < 3; ++k) {
        if (((axes[i] >> k) & 1U) == 0) continue;
        const Vec3 ak = current.r.col(k);
        const double c = ak.dot(rel) - src[i][k];
        Eigen::Matrix<double, 6, 1> j;
        j.head<3>() = ak.cross(dst[i] - centre);
        j.tail<3>() = -ak;
        a += weights[i] * j * j.transpose();
        b -= weights[i] * j * c;
      }
    }
    const Eigen::Matrix<double, 6, 1> u = a.ldlt().solve(b);
    if (!u.allFinite()) break;
    const Vec3 w = u.head<3>();
    const double angle = w.norm();
    const Eigen::Matrix3d turn =
        angle > 0 ? Eigen::AngleAxisd(angle, w / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
    // Turning about the centre: t' = centre + turn·(t − centre) + s.
    current.t = centre + turn * (current.t - centre) + u.tail<3>();
    current.r = nearest_rotation(turn * current.r);
    if (u.tail<3>().norm() < 1e-7 && angle < 1e-9) break;
  }
  return current;
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
                                const RobustFitOptions& options, std::vector<double>* weights_out,
                                std::span<const std::uint8_t> axes) {
  RigidTransform current = start;
  std::vector<double> residuals(src.size()), weights;
  const bool masked = any_masked(axes);
  auto residual = [&](size_t i) {
    return masked ? masked_distance(current, src[i], dst[i], axes[i]) : (current.apply(src[i]) - dst[i]).norm();
  };
  for (int it = 0; it < options.max_iterations; ++it) {
    for (size_t i = 0; i < src.size(); ++i) residuals[i] = residual(i);
    huber_weights(residuals, options, weights);
    const RigidTransform next =
        masked ? weighted_masked_fit(src, dst, axes, weights, current) : weighted_kabsch(src, dst, weights);
    double moved = 0;
    for (size_t i = 0; i < src.size(); i += std::max<size_t>(1, src.size() / 64))
      moved = std::max(moved, (next.apply(src[i]) - current.apply(src[i])).norm());
    current = next;
    if (moved < options.tolerance_mm) break;
  }
  if (weights_out != nullptr) {
    for (size_t i = 0; i < src.size(); ++i) residuals[i] = residual(i);
    huber_weights(residuals, options, *weights_out);
  }
  return current;
}

}  // namespace lmc
