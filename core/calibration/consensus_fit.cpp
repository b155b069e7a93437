#include "core/calibration/consensus_fit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/angles.h"

namespace lmc {

SampleTable::SampleTable(const std::vector<DeviceSamples>& samples, int frames)
    : devices_(static_cast<int>(samples.size())),
      index_(static_cast<size_t>(std::max(frames, 0)) * kNumCalibrationPoints * samples.size(), -1) {
  for (int d = 0; d < devices_; ++d) {
    const DeviceSamples& s = samples[static_cast<size_t>(d)];
    for (int i = 0; i < s.size(); ++i)
      if (s.frame[static_cast<size_t>(i)] < frames)
        index_[static_cast<size_t>(s.key(i)) * static_cast<size_t>(devices_) + static_cast<size_t>(d)] = i;
  }
}

void leave_one_out_pairs(const std::vector<DeviceSamples>& samples, const SampleTable& table,
                         const std::vector<RigidTransform>& transforms, const std::vector<bool>& included, int d,
                         std::vector<Vec3>& src, std::vector<Vec3>& dst, std::vector<int>& sample_index,
                         std::vector<std::uint8_t>* axes) {
  src.clear();
  dst.clear();
  sample_index.clear();
  if (axes != nullptr) axes->clear();
  const DeviceSamples& own = samples[static_cast<size_t>(d)];
  for (int i = 0; i < own.size(); ++i) {
    const int key = own.key(i);
    Vec3 sum = Vec3::Zero();
    int n = 0;
    for (int e = 0; e < table.devices(); ++e) {
      if (e == d || !included[static_cast<size_t>(e)]) continue;
      const int j = table.at(key, e);
      if (j < 0 || samples[static_cast<size_t>(e)].axes[static_cast<size_t>(j)] != kAllAxes) continue;
      sum += transforms[static_cast<size_t>(e)].apply(samples[static_cast<size_t>(e)].p[static_cast<size_t>(j)]);
      ++n;
    }
    if (n == 0) continue;
    src.push_back(own.p[static_cast<size_t>(i)]);
    dst.push_back(sum / n);
    sample_index.push_back(i);
    if (axes != nullptr) axes->push_back(own.axes[static_cast<size_t>(i)]);
  }
}

RigidTransform mean_correction(const std::vector<RigidTransform>& transforms,
                               const std::vector<RigidTransform>& nominal, const std::vector<bool>& included) {
  Eigen::Matrix3d rsum = Eigen::Matrix3d::Zero();
  Vec3 tsum = Vec3::Zero();
  int n = 0;
  for (size_t d = 0; d < transforms.size(); ++d) {
    if (!included[d]) continue;
    const RigidTransform c = transforms[d].compose(nominal[d].inverse());
    rsum += c.r;
    tsum += c.t;
    ++n;
  }
  if (n == 0) return {};
  return {nearest_rotation(rsum / n), tsum / n};
}

std::vector<RigidTransform> anchor_to_nominal(const std::vector<RigidTransform>& transforms,
                                              const std::vector<RigidTransform>& nominal,
                                              const std::vector<bool>& included) {
  // G = M⁻¹ for the mean correction M: afterwards the mean correction is the identity.
  const RigidTransform g = mean_correction(transforms, nominal, included).inverse();
  std::vector<RigidTransform> out = transforms;
  for (size_t d = 0; d < out.size(); ++d)
    if (included[d]) out[d] = g.compose(transforms[d]);
  return out;
}

namespace {

double change_mm(const RigidTransform& a, const RigidTransform& b) {
  const double turn_rad = rotation_angle_deg(a.r.transpose() * b.r) * kRadPerDeg;
  return std::max((a.t - b.t).norm(), 100.0 * turn_rad);
}

}  // namespace

ConsensusFit fit_consensus(const std::vector<DeviceSamples>& samples, const SampleTable& table,
                           const std::vector<RigidTransform>& nominal, const std::vector<bool>& included,
                           const ConsensusOptions& options) {
  ConsensusFit fit;
  fit.transforms = nominal;
  std::vector<Vec3> src, dst;
  std::vector<int> index;
  std::vector<std::uint8_t> axes;
  std::vector<double> residuals, weights;
  for (int sweep = 0; sweep < options.max_sweeps; ++sweep) {
    const std::vector<RigidTransform> before = fit.transforms;
    // Gauss–Seidel: each controller is refitted against the others' latest transforms; one
    // reweighting step per sweep, since the targets move between sweeps anyway.
    for (int d = 0; d < table.devices(); ++d) {
      if (!included[static_cast<size_t>(d)]) continue;
      leave_one_out_pairs(samples, table, fit.transforms, included, d, src, dst, index, &axes);
      if (src.size() < 3) continue;
      auto& t = fit.transforms[static_cast<size_t>(d)];
      residuals.resize(src.size());
      for (size_t i = 0; i < src.size(); ++i) residuals[i] = masked_distance(t, src[i], dst[i], axes[i]);
      huber_weights(residuals, options.fit, weights);
      // A controller with clamped samples has no closed-form fit (rigid_transform.h).
      t = any_masked(axes) ? weighted_masked_fit(src, dst, axes, weights, t) : weighted_kabsch(src, dst, weights);
    }
    fit.transforms = anchor_to_nominal(fit.transforms, nominal, included);
    fit.sweeps = sweep + 1;
    double moved = 0;
    for (size_t d = 0; d < before.size(); ++d) moved = std::max(moved, change_mm(before[d], fit.transforms[d]));
    if (moved < options.tolerance_mm) {
      fit.converged = true;
      break;
    }
  }
  return fit;
}

}  // namespace lmc
