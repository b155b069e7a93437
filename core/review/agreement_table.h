#pragma once
// LMC-vs-Vicon agreement per layout × pose, for every finger length and joint ROM: what a
// validation paper reports (Bland–Altman bias and limits, RMSE, Pearson r, ICC) rather than the
// mean ± SD tables of `lmc report`. Every statistic comes from core/stats; this file only decides
// which trials enter which statistic and which form of it applies.
//
// Differences are LMC − Vicon. A trial is one observation (its per-trial value). The pairs of one
// measure in one group are those trials where both values are present; a trial with a null on
// either side is skipped and counted for that measure only.
#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/review/agreement_input.h"
#include "core/stats/bland_altman.h"
#include "core/stats/descriptives.h"
#include "core/stats/icc.h"
#include "core/stats/pearson.h"

namespace lmc {

struct AgreementOptions {
  // Also pool every trial into one "all" × "all" group (listed last): the headline numbers.
  bool include_all_group = true;
  // Keep only trials of this motion (empty: every motion). A joint's ROM means something else in
  // a static trial than in a wrist-flexion trial, so a UI may want one motion at a time.
  std::string motion;
};

// One point of a Bland–Altman plot, with the subject so a UI can colour by subject.
struct AgreementPoint {
  double mean = 0.0;        // (LMC + Vicon) / 2
  double difference = 0.0;  // LMC − Vicon
  std::string subject;
  std::string trial;
};

// The fewest complete trials an ICC's confidence interval is given for.
inline constexpr std::size_t kMinTrialsForIccInterval = 4;

struct MeasureAgreement {
  AgreementMeasure measure;
  std::size_t n_trials = 0;    // complete pairs
  std::size_t n_skipped = 0;   // trials of the group with a null on either side
  std::size_t n_subjects = 0;  // subjects with at least one complete pair
  // Several trials of one subject are not independent: the repeated-measures form (B&A 2007) is
  // used as soon as one subject has more than one complete pair, else the one-pair-per-subject
  // form; `bland_altman.method` names the one used.
  BlandAltmanResult bland_altman;
  PairedDescriptives differences;  // mean ± SD of LMC − Vicon, RMSE (A = LMC, B = Vicon)
  PearsonResult pearson;
  // ICC(2,1) of the n_trials × 2 table (LMC, Vicon): trials are the targets, the two systems the
  // raters, absolute agreement — a constant offset between systems lowers it, as it should.
  IccEstimate icc;
  std::string icc_reason;  // why icc or its interval is NaN; empty when both are valid
  std::vector<AgreementPoint> points;
};

struct AgreementGroup {
  std::string layout;        // "all" in the pooled group
  std::string pose;          // "all" in the pooled group
  std::size_t n_trials = 0;  // trials with Vicon in the group
  std::size_t n_subjects = 0;
  std::vector<MeasureAgreement> measures;  // in agreement_measures() order
};

struct AgreementTable {
  std::vector<AgreementGroup> groups;  // layout × pose in name order, then "all"
  std::size_t trials = 0;              // trials given (after the motion filter)
  std::size_t trials_without_vicon = 0;
};

AgreementTable agreement_table(const std::vector<AgreementTrial>& trials, const AgreementOptions& options = {});

// One header row, then one row per group × measure. Missing numbers are empty cells (never 0);
// the Bland–Altman method and the ICC form are written out so the table says how it was computed.
std::string agreement_csv(const AgreementTable& table);

void to_json(nlohmann::json& j, const AgreementPoint& p);
void to_json(nlohmann::json& j, const MeasureAgreement& m);
void to_json(nlohmann::json& j, const AgreementGroup& g);
void to_json(nlohmann::json& j, const AgreementTable& t);

}  // namespace lmc
