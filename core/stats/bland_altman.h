#pragma once
// Bland–Altman agreement between two methods measuring the same quantity: differences d = A − B
// (A the method under test, e.g. fused LMC; B the reference, e.g. Vicon), their mean (the bias) and
// the 95 % limits of agreement bias ± z·SD with z = z_{0.975} = 1.95996 (Boost's normal quantile;
// the papers round it to 1.96).
//
// bland_altman(): one pair per subject (Bland & Altman 1986, Lancet 327:307–310; 1999, Stat Methods
// Med Res 8:135–160):
//   bias CI   = bias ± t_{0.975, n−1} · s/√n
//   limit CIs = limit ± t_{0.975, n−1} · sqrt(3 s²/n)   (their approximate SE of a limit)
//
// Several trials of one subject are not independent; pooling them as if they were makes the
// limits too narrow. Use bland_altman_repeated() (bland_altman_repeated.h) for that case.
#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <vector>

#include "core/stats/interval.h"

namespace lmc {

struct BlandAltmanResult {
  std::string method;         // the form and the interval method used (also exported)
  std::size_t n_used = 0;     // complete pairs (observations) used
  std::size_t n_skipped = 0;  // pairs with a missing value on either side
  // subjects with at least one complete pair (= n_used in the simple form)
  std::size_t n_subjects = 0;
  double bias = kNaN;               // mean of A − B
  double sd_difference = kNaN;      // SD of A − B (repeated form: sqrt(between² + within²))
  double loa_low = kNaN;            // bias − z·sd_difference
  double loa_high = kNaN;           // bias + z·sd_difference
  Interval bias_ci;                 // 95 %
  Interval loa_low_ci;              // 95 %
  Interval loa_high_ci;             // 95 %
  double within_subject_sd = kNaN;  // repeated form only: sqrt(s²_dw)
  // repeated form only: sqrt(s²_db), 0 when its estimate (MS_b − MS_w)/c is negative
  double between_subject_sd = kNaN;
  double loa_multiplier = kNaN;  // z_{0.975}
  std::string reason;            // why (some of) the numbers are NaN; empty when all are valid
  bool ok() const { return reason.empty(); }
};

// Throws lmc::Error when a and b differ in length. Fewer than 2 complete pairs: NaN and a reason.
BlandAltmanResult bland_altman(std::span<const double> a, std::span<const double> b);

// One point of a Bland–Altman plot: x = (A + B)/2, y = A − B.
struct BlandAltmanPoint {
  double mean = kNaN;
  double difference = kNaN;
};

// The plot's points for the complete pairs, in input order (incomplete pairs are left out, as in
// bland_altman()). Throws lmc::Error when a and b differ in length.
std::vector<BlandAltmanPoint> bland_altman_points(std::span<const double> a, std::span<const double> b);

void to_json(nlohmann::json& j, const BlandAltmanResult& r);

}  // namespace lmc
