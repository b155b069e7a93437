#include "core/review/agreement_table.h"

#include <Eigen/Core>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <utility>

#include "core/common/csv_cell.h"
#include "core/common/nan.h"
#include "core/common/number_format.h"
#include "core/stats/bland_altman_repeated.h"
#include "core/stats/paired_values.h"

namespace lmc {

namespace {

using AgreementRows = std::vector<const PairedTrial*>;

MeasureAgreement agree_on_measure(const AgreementRows& rows, std::size_t i) {
  MeasureAgreement m;
  m.measure = agreement_measures()[i];
  // Every trial goes to the statistics, incomplete ones too, so each counts its own skipped pairs.
  std::vector<double> lmc_values, vicon_values;
  std::vector<PairedObservation> observations;
  std::map<std::string, std::size_t> pairs_per_subject;
  for (const PairedTrial* t : rows) {
    lmc_values.push_back(t->lmc[i]);
    vicon_values.push_back(t->vicon[i]);
    observations.push_back({t->subject, t->lmc[i], t->vicon[i]});
    if (is_usable(t->lmc[i]) && is_usable(t->vicon[i])) {
      ++pairs_per_subject[t->subject];
      ++m.n_trials;
    } else {
      ++m.n_skipped;
    }
  }
  m.n_subjects = pairs_per_subject.size();
  bool repeated = false;
  for (const auto& [subject, n] : pairs_per_subject) repeated = repeated || n > 1;
  m.bland_altman = repeated ? bland_altman_repeated(observations) : bland_altman(lmc_values, vicon_values);
  m.differences = describe_pairs(lmc_values, vicon_values);
  m.pearson = pearson(lmc_values, vicon_values);

  Eigen::MatrixXd ratings(static_cast<Eigen::Index>(rows.size()), 2);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    ratings(static_cast<Eigen::Index>(r), 0) = lmc_values[r];
    ratings(static_cast<Eigen::Index>(r), 1) = vicon_values[r];
  }
  const IccResult icc_result = icc(ratings);
  m.icc = icc_result.icc2_1;
  m.icc_reason = icc_result.reason;
  // From 2 or 3 trials the interval spans nearly every value an ICC can take and rests on the
  // normality of a handful of values: not given, and the reason says so (as Pearson's r needs 4
  // pairs for its interval).
  if (m.icc_reason.empty() && m.n_trials < kMinTrialsForIccInterval) {
    m.icc.ci = {};
    m.icc_reason = "no interval from " + std::to_string(m.n_trials) + " trials: it needs at least " +
                   std::to_string(kMinTrialsForIccInterval);
  }

  // bland_altman_points() keeps the complete pairs in input order; walk the rows alike to name
  // them.
  const auto points = bland_altman_points(lmc_values, vicon_values);
  std::size_t next = 0;
  for (const PairedTrial* t : rows) {
    if (!is_usable(t->lmc[i]) || !is_usable(t->vicon[i])) continue;
    m.points.push_back({points[next].mean, points[next].difference, t->subject, t->trial});
    ++next;
  }
  return m;
}

AgreementGroup agree_on_group(std::string layout, std::string pose, const AgreementRows& rows) {
  AgreementGroup g;
  g.layout = std::move(layout);
  g.pose = std::move(pose);
  g.n_trials = rows.size();
  std::set<std::string> subjects;
  for (const PairedTrial* t : rows) subjects.insert(t->subject);
  g.n_subjects = subjects.size();
  for (std::size_t i = 0; i < kAgreementMeasures; ++i) g.measures.push_back(agree_on_measure(rows, i));
  return g;
}

// Empty for NaN / ±inf: an empty cell reads as missing in a spreadsheet; "0" or "nan" would not.
std::string agreement_number(double v) {
  return is_usable(v) ? format_fixed(v, 6) : std::string();
}

std::string agreement_notes(const MeasureAgreement& m) {
  std::string notes;
  const auto add = [&notes](const char* what, const std::string& reason) {
    if (reason.empty()) return;
    if (!notes.empty()) notes += "; ";
    notes += std::string(what) + ": " + reason;
  };
  add("Bland-Altman", m.bland_altman.reason);
  add("differences", m.differences.reason);
  add("Pearson", m.pearson.reason);
  add("ICC", m.icc_reason);
  return notes;
}

}  // namespace

AgreementTable agreement_table(const std::vector<AgreementTrial>& trials, const AgreementOptions& options) {
  AgreementTable table;
  std::vector<AgreementTrial> selected;
  for (const AgreementTrial& t : trials)
    if (options.motion.empty() || t.motion == options.motion) selected.push_back(t);
  table.trials = selected.size();
  const PairedTrials paired = extract_paired_trials(selected);
  table.trials_without_vicon = paired.without_vicon;

  std::map<std::pair<std::string, std::string>, AgreementRows> groups;
  AgreementRows all;
  for (const PairedTrial& t : paired.trials) {
    groups[{t.layout, t.pose}].push_back(&t);
    all.push_back(&t);
  }
  for (const auto& [key, rows] : groups) table.groups.push_back(agree_on_group(key.first, key.second, rows));
  if (options.include_all_group) table.groups.push_back(agree_on_group("all", "all", all));
  return table;
}

std::string agreement_csv(const AgreementTable& table) {
  std::ostringstream csv;
  csv << "layout,pose,measure,quantity,part,unit,n_trials,n_skipped,n_subjects,lmc_mean,vicon_mean,"
         "diff_mean,diff_sd,"
         "mean_abs_diff,rmse,ba_method,ba_bias,ba_bias_ci_low,ba_bias_ci_high,ba_sd,ba_loa_low,ba_"
         "loa_low_ci_low,"
         "ba_loa_low_ci_high,ba_loa_high,ba_loa_high_ci_low,ba_loa_high_ci_high,ba_within_subject_"
         "sd,"
         "ba_between_subject_sd,pearson_r,pearson_ci_low,pearson_ci_high,icc_form,icc_description,"
         "icc,icc_ci_low,"
         "icc_ci_high,notes\n";
  for (const AgreementGroup& g : table.groups) {
    for (const MeasureAgreement& m : g.measures) {
      const auto& ba = m.bland_altman;
      const auto& d = m.differences;
      csv << csv_cell(g.layout) << ',' << csv_cell(g.pose) << ',' << m.measure.name << ',' << m.measure.quantity << ','
          << m.measure.part << ',' << m.measure.unit << ',' << m.n_trials << ',' << m.n_skipped << ',' << m.n_subjects;
      for (double v : {d.mean_a, d.mean_b, d.mean_difference, d.sd_difference, d.mean_abs_difference, d.rmse})
        csv << ',' << agreement_number(v);
      csv << ',' << csv_cell(ba.method);
      for (double v : {ba.bias, ba.bias_ci.low, ba.bias_ci.high, ba.sd_difference, ba.loa_low, ba.loa_low_ci.low,
                       ba.loa_low_ci.high, ba.loa_high, ba.loa_high_ci.low, ba.loa_high_ci.high, ba.within_subject_sd,
                       ba.between_subject_sd, m.pearson.r, m.pearson.ci.low, m.pearson.ci.high})
        csv << ',' << agreement_number(v);
      csv << ',' << csv_cell(m.icc.form) << ',' << csv_cell(m.icc.description);
      for (double v : {m.icc.value, m.icc.ci.low, m.icc.ci.high}) csv << ',' << agreement_number(v);
      csv << ',' << csv_cell(agreement_notes(m)) << '\n';
    }
  }
  return csv.str();
}

void to_json(nlohmann::json& j, const AgreementPoint& p) {
  j = nlohmann::json{{"mean", p.mean}, {"difference", p.difference}, {"subject", p.subject}, {"trial", p.trial}};
}

void to_json(nlohmann::json& j, const MeasureAgreement& m) {
  j = nlohmann::json{{"measure", m.measure.name},      {"quantity", m.measure.quantity},
                     {"part", m.measure.part},         {"unit", m.measure.unit},
                     {"n_trials", m.n_trials},         {"n_skipped", m.n_skipped},
                     {"n_subjects", m.n_subjects},     {"difference", "LMC - Vicon"},
                     {"bland_altman", m.bland_altman}, {"differences", m.differences},
                     {"pearson", m.pearson},           {"icc", m.icc},
                     {"icc_reason", m.icc_reason},     {"points", m.points}};
}

void to_json(nlohmann::json& j, const AgreementGroup& g) {
  j = nlohmann::json{{"layout", g.layout},
                     {"pose", g.pose},
                     {"n_trials", g.n_trials},
                     {"n_subjects", g.n_subjects},
                     {"measures", g.measures}};
}

void to_json(nlohmann::json& j, const AgreementTable& t) {
  j = nlohmann::json{{"trials", t.trials}, {"trials_without_vicon", t.trials_without_vicon}, {"groups", t.groups}};
}

}  // namespace lmc
