#pragma once
// Intraclass correlation coefficients of an n × k table (rows: targets, e.g. subjects or trials;
// columns: raters or methods, e.g. LMC and Vicon), following Shrout & Fleiss (1979), Psychol Bull
// 86:420–428, with McGraw & Wong's (1996, Psychol Methods 1:30–46) names for model and type.
//
// From the two-way ANOVA of the table (S&F's notation):
//   BMS between targets (n − 1 df), WMS within targets (n(k − 1) df),
//   JMS between judges (k − 1 df), EMS residual ((n − 1)(k − 1) df)
//   ICC(1,1) = (BMS − WMS) / (BMS + (k − 1) WMS)
//              one-way random effects, absolute agreement
//   ICC(2,1) = (BMS − EMS) / (BMS + (k − 1) EMS + k (JMS − EMS)/n)
//              two-way random effects, absolute agreement
//   ICC(3,1) = (BMS − EMS) / (BMS + (k − 1) EMS)
//              two-way mixed effects, consistency
//   ICC(1,k) = (BMS − WMS) / BMS,  ICC(2,k) = (BMS − EMS) / (BMS + (JMS − EMS)/n),
//   ICC(3,k) = (BMS − EMS) / BMS   (the reliability of the mean of the k ratings)
// 95 % intervals from the F distribution: exact for ICC(1,·) and ICC(3,·) (S&F eqs. for F = BMS/WMS
// and BMS/EMS); for ICC(2,·) S&F's approximate F with Satterthwaite's degrees of freedom, the
// average-measures bounds being McGraw & Wong's (Spearman–Brown of the single-measure bounds).
// Each estimate also carries its F test of ICC = 0 (S&F's F0, df and upper-tail p value).
//
// Koo & Li (2016) read an ICC below 0.5 as poor, 0.5–0.75 moderate, 0.75–0.9 good, above 0.9
// excellent; they recommend reporting the form used, as `description` does.
#include <Eigen/Core>
#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "core/stats/interval.h"

namespace lmc {

struct IccEstimate {
  std::string form;  // "ICC(2,1)", "ICC(3,4)", …
  // e.g. "ICC(2,1): two-way random effects, absolute agreement, single measurement"
  std::string description;
  double value = kNaN;
  Interval ci;            // 95 %
  double f_value = kNaN;  // F test of ICC = 0
  double f_df1 = kNaN;
  double f_df2 = kNaN;
  double p_value = kNaN;
};

struct IccResult {
  std::size_t n_targets = 0;                              // rows used (complete)
  std::size_t n_dropped = 0;                              // rows left out because they held a NaN / ±inf
  std::size_t k = 0;                                      // columns (raters / methods)
  double bms = kNaN, wms = kNaN, jms = kNaN, ems = kNaN;  // the ANOVA mean squares above
  IccEstimate icc1_1, icc2_1, icc3_1;                     // single measurement
  IccEstimate icc1_k, icc2_k, icc3_k;                     // average of k measurements
  std::string reason;                                     // why the numbers are NaN; empty when they are valid
  bool ok() const { return reason.empty(); }
};

// Rows with a missing value are dropped and counted. Fewer than 2 complete rows or fewer than 2
// columns: NaN and a reason. No variation at all (every value equal): NaN and a reason.
IccResult icc(const Eigen::MatrixXd& ratings);

void to_json(nlohmann::json& j, const IccEstimate& e);
void to_json(nlohmann::json& j, const IccResult& r);

}  // namespace lmc
