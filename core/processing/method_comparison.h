#pragma once
// "Better than the study, measured": per-frame errors of fused finger lengths and joint angles
// against truth (a simulated trial's ground-truth TRC, or Vicon), as RMSE, overall and on the
// frames where at least one device could not see the finger (its label for that finger is 0 or
// −1): exactly the frames where fusion has to cope with guesses or missing data. An angle belongs
// to its finger (index MCP/PIP/DIP → index, thumb MCP/DIP → thumb); the wrist angle counts as
// "not seen" when some device misses any finger.
#include <array>
#include <string>
#include <vector>

#include "core/processing/trial_pipeline.h"

namespace lmc {

struct ErrorAccumulator {
  double sum_sq = 0;
  long count = 0;
  void add(double e) {
    sum_sq += e * e;
    ++count;
  }
  void merge(const ErrorAccumulator& o) {
    sum_sq += o.sum_sq;
    count += o.count;
  }
  double rmse() const;  // NaN when empty
};

struct MethodErrors {
  std::array<ErrorAccumulator, kNumFingers> finger_all{}, finger_unseen{};
  std::array<ErrorAccumulator, kNumAngles> angle_all{}, angle_unseen{};
  // Coverage: (finger, frame) pairs with a truth value, and those where this method gave one.
  long truth_values = 0, method_values = 0;
  void merge(const MethodErrors& o);
  // Pooled over fingers / angles.
  ErrorAccumulator finger_pooled(bool unseen) const;
  ErrorAccumulator angle_pooled(bool unseen) const;
};

// Errors of one processed trial (needs Vicon/truth). Frames where LMC or truth is NaN are skipped;
// with `other` (the same trial by the other method) also frames where the other method is NaN, so
// both methods are scored on the same frames. (The reference filter can turn NaN for good: when
// two devices' rolling variances are 0 — a clipped, constant coordinate — its update divides 0
// by 0, as the study's did; the default method leaves NaN where no device saw the hand for longer
// than the gap limit.)
MethodErrors trial_errors(const TrialAnalysis& r, const TrialAnalysis* other = nullptr);

// A Markdown table: rows = measure (finger lengths pooled and per finger, angles pooled and per
// joint), columns = reference / default RMSE overall and on not-seen frames, with frame counts.
std::string method_comparison_markdown(const MethodErrors& reference, const MethodErrors& fused_default, int trials);

}  // namespace lmc
