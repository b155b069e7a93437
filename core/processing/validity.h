#pragma once
// One trial's validity figures for one fusion method: finger lengths and joint angles
// against Vicon (bias = mean LMC − Vicon over the compared frames, RMSE), and the consensus
// measures that need no Vicon (consensus.h): fused lengths against the controllers that see the
// finger. `lmc validate` prints them for every method, real recordings before simulated ones.
#include <array>
#include <string>

#include "core/processing/consensus.h"
#include "core/processing/trial_pipeline.h"

namespace lmc {

struct MethodValidity {
  FusionMethod method = FusionMethod::kDefault;
  std::string label;                              // the rows' short name for it; empty: the method's own ("default")
  std::array<double, kNumFingers> finger_mean{};  // fused, all frames with a hand
  std::array<double, kNumFingers> vicon_finger_mean{};           // NaN without Vicon
  std::array<double, kNumFingers> finger_bias{}, finger_rmse{};  // LMC − Vicon per frame
  std::array<double, kNumAngles> angle_bias{}, angle_rmse{};
  ConsensusReport consensus;
};

MethodValidity method_validity(const TrialAnalysis& result);

// A plain-text table of several methods on one trial: finger lengths (Vicon, each method, the
// seeing controllers' median and range), fused − median, shortest seeing controller, point
// distance, then bias and RMSE against Vicon for fingers and angles.
std::string format_validity(const std::string& title, const std::vector<MethodValidity>& methods);

}  // namespace lmc
