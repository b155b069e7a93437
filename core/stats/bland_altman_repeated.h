#pragma once
// Bland–Altman limits of agreement when a subject has several observations (trials) and the true
// value may differ between them: Bland & Altman 2007, "Agreement between methods of measurement
// with multiple observations per individual", J Biopharm Stat 17:571–582, §5.
//
// With subjects i = 1..n, m_i complete pairs each (N = Σ m_i) and differences d_ij = A − B, a
// one-way ANOVA of d by subject gives MS_between (n − 1 df) and MS_within (N − n df); then
//   s²_dw = MS_within                                       (within-subject variance)
//   s²_db = (MS_between − MS_within) / c,  c = (N² − Σ m_i²) / ((n − 1) N)   (0 when negative)
//   SD    = sqrt(s²_db + s²_dw),  bias = mean of all N differences,  limits = bias ± z_{0.975}·SD.
// c is the average number of observations per subject corrected for unequal m_i; c ≥ 1 always.
//
// Confidence intervals (approximate):
//   bias:   bias ± t_{0.975, n−1} · sqrt(s²_db Σ m_i²/N² + s²_dw/N)   (variance of the grand mean
//           under the random-subject model, subjects as the unit of replication)
//   limits: MOVER, the method of variance estimates recovery (Zou 2013, Stat Methods Med Res
//           22:630–642). SD² = MS_between/c + (1 − 1/c)·MS_within is a sum of two independent
//           scaled χ² mean squares; each term gets its exact χ² interval, the MOVER combines them
//           into an interval [L, U] for SD², and again combines the bias interval with
//           [z·√L, z·√U] for each limit. When s²_db is truncated at 0 the variance interval is
//           widened, if needed, to contain the truncated estimate.
//           Zou writes SD² as (variance of the subject means) + (1 − 1/m_h)·MS_within with m_h the
//           harmonic mean of m_i; with equal m_i that is the same sum and the same interval. With
//           unequal m_i this module keeps B&A 2007's ANOVA estimate (c in place of m_h) so the
//           interval is built around the SD it reports. The bias uses t(n − 1), not z.
//
// Reduction to the simple form: if every subject has the same number of repeats m and the repeats
// of a subject are identical, then s²_dw = 0, c = m and s²_db = the variance of the subject means,
// so bias, SD, the limits and the bias CI equal bland_altman() on one difference per subject; the
// limit CIs then come from the χ²(n − 1) interval of s² (MOVER) instead of sqrt(3 s²/n). With one
// observation per subject (all m_i = 1) everything except the limit CIs equals bland_altman() too.
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>

#include "core/stats/bland_altman.h"

namespace lmc {

struct PairedObservation {
  std::string subject;  // groups the trials of one subject
  double a = kNaN;      // method under test
  double b = kNaN;      // reference
};

// Observations with a missing value on either side are skipped and counted; a subject with no
// complete observation disappears. Needs ≥ 2 subjects for the SD, the limits and every CI (NaN
// and a reason otherwise); with one subject the bias (the mean of its differences) and the
// within-subject SD are still given, with the reason saying what is missing.
BlandAltmanResult bland_altman_repeated(std::span<const PairedObservation> observations);

}  // namespace lmc
