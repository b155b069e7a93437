#pragma once
// Calibration without Vicon: every controller refined jointly against what the others see
// (generalised Procrustes). The target of a controller's point is the mean of the *other*
// controllers' same point on the same frame, so a controller is never pulled towards itself;
// each sweep refits the controllers in order (Huber-weighted Kabsch, rigid_transform.h) and then
// re-anchors the set.
//
// Anchoring: agreement between controllers says nothing about where the set stands as a whole,
// so the whole set could turn or slide. After every sweep a common transform G is applied to
// every controller so that the mean correction is the identity: the corrections
// C_d = T_d ∘ N_d⁻¹ (world → world, N_d nominal) have mean rotation (the rotation nearest their
// average) I and mean translation 0. The layout's nominal world frame is thus kept on average,
// and a controller's correction is relative to the others.
#include <vector>

#include "core/calibration/calibration_samples.h"
#include "core/calibration/rigid_transform.h"

namespace lmc {

// Which samples of which controllers share a (frame, point).
class SampleTable {
 public:
  SampleTable(const std::vector<DeviceSamples>& samples, int frames);
  // Index of device d's sample with this key, or −1.
  int at(int key, int d) const {
    return index_[static_cast<size_t>(key) * static_cast<size_t>(devices_) + static_cast<size_t>(d)];
  }
  int devices() const { return devices_; }

 private:
  int devices_ = 0;
  std::vector<int> index_;
};

// For device d, its samples that at least one other `included` device shares: src = d's point
// (device coordinates), dst = mean of the others' points under `transforms`; `sample_index` is the
// sample each pair came from, `axes` (optional) the device axes of src the fit may use. Only whole
// samples of the others make a target: a clamped point's place is not known in every direction.
void leave_one_out_pairs(const std::vector<DeviceSamples>& samples, const SampleTable& table,
                         const std::vector<RigidTransform>& transforms, const std::vector<bool>& included, int d,
                         std::vector<Vec3>& src, std::vector<Vec3>& dst, std::vector<int>& sample_index,
                         std::vector<std::uint8_t>* axes = nullptr);

// The mean correction of the `included` controllers: the rotation nearest the average of
// T_d ∘ N_d⁻¹'s rotations and the average of their translations (identity when none is included).
RigidTransform mean_correction(const std::vector<RigidTransform>& transforms,
                               const std::vector<RigidTransform>& nominal, const std::vector<bool>& included);

// The common transform applied to every `included` controller so that their mean correction
// relative to `nominal` is the identity (see above). Returns the anchored transforms.
std::vector<RigidTransform> anchor_to_nominal(const std::vector<RigidTransform>& transforms,
                                              const std::vector<RigidTransform>& nominal,
                                              const std::vector<bool>& included);

struct ConsensusOptions {
  RobustFitOptions fit;
  int max_sweeps = 400;
  double tolerance_mm = 1e-4;  // stop when no controller moves (or turns, at 100 mm) more than this
};

struct ConsensusFit {
  std::vector<RigidTransform> transforms;
  int sweeps = 0;
  bool converged = false;
};

// Controllers not `included` keep their nominal transform and take no part.
ConsensusFit fit_consensus(const std::vector<DeviceSamples>& samples, const SampleTable& table,
                           const std::vector<RigidTransform>& nominal, const std::vector<bool>& included,
                           const ConsensusOptions& options);

}  // namespace lmc
