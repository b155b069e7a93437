#include "core/review/agreement_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/nan.h"
#include "core/review/agreement_input.h"
#include "core/stats/pearson.h"

namespace lmc::agreement_test {

nlohmann::json value_or_null(double v) {
  return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v);
}

// A summary as trial_summary.cpp writes it: every finger has length `*_len`, every joint ROM
// `*_rom`; NaN is written as null. The ROM difference is always −2°.
nlohmann::json trial_json(const std::string& trial, const std::string& layout, const std::string& pose,
                          const std::string& motion, double lmc_len, double vicon_len, bool with_vicon = true) {
  nlohmann::json s;
  s["trial"] = trial;
  s["tag"] = {{"layout", layout}, {"pose", pose}, {"motion", motion}, {"repetition", 1}, {"parsed", true}};
  s["method"] = "default";
  const double rom = std::isnan(vicon_len) ? 40.0 : vicon_len / 2.0;
  s["lmc"] = {{"finger_mean_mm", nlohmann::json::array()}, {"angle_rom_deg", nlohmann::json::array()}};
  s["vicon"] = {{"finger_mean_mm", nlohmann::json::array()}, {"angle_rom_deg", nlohmann::json::array()}};
  for (int k = 0; k < 5; ++k) {
    s["lmc"]["finger_mean_mm"].push_back(value_or_null(lmc_len));
    s["vicon"]["finger_mean_mm"].push_back(value_or_null(vicon_len));
  }
  for (int k = 0; k < 6; ++k) {
    s["lmc"]["angle_rom_deg"].push_back(rom - 2.0);
    s["vicon"]["angle_rom_deg"].push_back(value_or_null(std::isnan(vicon_len) ? kNaN : rom));
  }
  if (!with_vicon) s.erase("vicon");
  return s;
}

AgreementTrial paired(const std::string& subject, const std::string& layout, const std::string& pose, double lmc_len,
                      double vicon_len) {
  return agreement_trial(subject,
                         trial_json(subject + "_" + layout + "_" + pose, layout, pose, "index", lmc_len, vicon_len));
}

// 3 subjects × 2 trials (initial, horizontal), differences LMC − Vicon S1: 1, 3; S2: 3, 5;
// S3: 5, 7 on varying Vicon lengths; 3 subjects × 1 trial (optimized, vertical), differences 1,
// 2, 6.
std::vector<AgreementTrial> study_trials() {
  return {paired("S1", "initial", "horizontal", 51, 50), paired("S1", "initial", "horizontal", 63, 60),
          paired("S2", "initial", "horizontal", 58, 55), paired("S2", "initial", "horizontal", 70, 65),
          paired("S3", "initial", "horizontal", 75, 70), paired("S3", "initial", "horizontal", 59, 52),
          paired("S1", "optimized", "vertical", 61, 60), paired("S2", "optimized", "vertical", 57, 55),
          paired("S3", "optimized", "vertical", 66, 60)};
}

const AgreementGroup& find_group(const AgreementTable& t, const std::string& layout, const std::string& pose) {
  for (const AgreementGroup& g : t.groups)
    if (g.layout == layout && g.pose == pose) return g;
  throw std::runtime_error("no group " + layout + " × " + pose);
}

// RFC 4180 cells of one line (quoted cells may hold commas).
std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      cells.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

std::vector<std::vector<std::string>> csv_rows(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);) rows.push_back(csv_cells(line));
  return rows;
}

std::string column(const std::vector<std::vector<std::string>>& rows, std::size_t row, const std::string& name) {
  for (std::size_t c = 0; c < rows[0].size(); ++c)
    if (rows[0][c] == name) return rows[row].at(c);
  throw std::runtime_error("no column " + name);
}

TEST(ReviewAgreement, ExtractsPairsFromTheSummaryAndSkipsTrialsWithoutVicon) {
  std::vector<AgreementTrial> trials = study_trials();
  trials.push_back(agreement_trial("S4", trial_json("Naiv_Index101", "initial", "horizontal", "index", 70, 80, false)));
  const PairedTrials p = extract_paired_trials(trials);
  EXPECT_EQ(p.without_vicon, 1u);
  ASSERT_EQ(p.trials.size(), 9u);
  EXPECT_EQ(p.trials[0].subject, "S1");
  EXPECT_EQ(p.trials[0].layout, "initial");
  EXPECT_EQ(p.trials[0].pose, "horizontal");
  EXPECT_EQ(p.trials[0].motion, "index");
  EXPECT_EQ(p.trials[0].trial, "S1_initial_horizontal");
  EXPECT_DOUBLE_EQ(p.trials[0].lmc[0], 51.0);     // thumb length
  EXPECT_DOUBLE_EQ(p.trials[0].vicon[4], 50.0);   // pinky length
  EXPECT_DOUBLE_EQ(p.trials[0].lmc[5], 23.0);     // index_mcp ROM
  EXPECT_DOUBLE_EQ(p.trials[0].vicon[10], 25.0);  // wrist ROM
  EXPECT_EQ(agreement_measures()[0].name, "finger_length_thumb");
  EXPECT_EQ(agreement_measures()[0].unit, "mm");
  EXPECT_EQ(agreement_measures()[10].name, "rom_wrist");
  EXPECT_EQ(agreement_measures()[10].unit, "deg");
}

// One subject, two trials: an ICC is computed but no interval is given for it, and each missing
// number says why (r from 2 pairs is undefined or ±1; limits need a second subject).
TEST(ReviewAgreement, TwoTrialsOfOneSubjectGiveNoIccIntervalAndSayWhy) {
  const AgreementTable t =
      agreement_table({paired("P01", "initial", "horizontal", 51, 50), paired("P01", "initial", "horizontal", 63, 60)});
  const MeasureAgreement& m = find_group(t, "initial", "horizontal").measures[0];
  EXPECT_EQ(m.n_trials, 2u);
  EXPECT_EQ(m.n_subjects, 1u);
  EXPECT_TRUE(std::isfinite(m.icc.value));
  EXPECT_FALSE(std::isfinite(m.icc.ci.low));
  EXPECT_FALSE(std::isfinite(m.icc.ci.high));
  EXPECT_EQ(m.icc_reason, "no interval from 2 trials: it needs at least 4");
  EXPECT_FALSE(std::isfinite(m.pearson.r));
  EXPECT_NE(m.pearson.reason.find("fewer than 3 complete pairs"), std::string::npos) << m.pearson.reason;
  // Four trials: the interval is given.
  const AgreementTable four =
      agreement_table({paired("P01", "initial", "horizontal", 51, 50), paired("P01", "initial", "horizontal", 63, 60),
                       paired("P02", "initial", "horizontal", 58, 55), paired("P02", "initial", "horizontal", 70, 65)});
  const MeasureAgreement& m4 = find_group(four, "initial", "horizontal").measures[0];
  EXPECT_TRUE(m4.icc_reason.empty()) << m4.icc_reason;
  EXPECT_TRUE(std::isfinite(m4.icc.ci.low));
}

TEST(ReviewAgreement, SeveralTrialsPerSubjectUseTheRepeatedForm) {
  const AgreementTable t = agreement_table(study_trials());
  const MeasureAgreement& m = find_group(t, "initial", "horizontal").measures[0];  // thumb length
  EXPECT_EQ(m.n_trials, 6u);
  EXPECT_EQ(m.n_subjects, 3u);
  EXPECT_EQ(m.n_skipped, 0u);
  // d = 1, 3, 3, 5, 5, 7: bias 4, Σd² = 118, Σ(d − 4)² = 22.
  EXPECT_NEAR(m.differences.mean_difference, 4.0, 1e-12);
  EXPECT_NEAR(m.differences.sd_difference, std::sqrt(22.0 / 5.0), 1e-12);
  EXPECT_NEAR(m.differences.rmse, std::sqrt(118.0 / 6.0), 1e-12);
  // One-way ANOVA by subject: subject means 2, 4, 6; MS_within = 6/3 = 2, MS_between = 16/2 = 8,
  // c = 2, s²_db = (8 − 2)/2 = 3; SD = sqrt(3 + 2).
  ASSERT_TRUE(m.bland_altman.ok()) << m.bland_altman.reason;
  EXPECT_NE(m.bland_altman.method.find("2007"), std::string::npos) << m.bland_altman.method;
  EXPECT_NEAR(m.bland_altman.bias, 4.0, 1e-12);
  EXPECT_NEAR(m.bland_altman.within_subject_sd, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(m.bland_altman.between_subject_sd, std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(m.bland_altman.sd_difference, std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(m.bland_altman.loa_low, 4.0 - 1.959963984540054 * std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(m.bland_altman.loa_high, 4.0 + 1.959963984540054 * std::sqrt(5.0), 1e-9);
  // Pearson and ICC on the six (LMC, Vicon) pairs.
  const std::vector<double> lmc = {51, 63, 58, 70, 75, 59}, vicon = {50, 60, 55, 65, 70, 52};
  const PearsonResult r = pearson(lmc, vicon);
  EXPECT_NEAR(m.pearson.r, r.r, 1e-12);
  EXPECT_NEAR(m.pearson.ci.low, r.ci.low, 1e-12);
  EXPECT_EQ(m.icc.form, "ICC(2,1)");
  EXPECT_EQ(m.icc.description, "ICC(2,1): two-way random effects, absolute agreement, single measurement");
  EXPECT_TRUE(m.icc_reason.empty()) << m.icc_reason;
  EXPECT_GT(m.icc.value, 0.0);
  EXPECT_LT(m.icc.value, r.r);  // the 4 mm bias costs absolute agreement, not correlation

  // ROM: every difference is −2°: bias −2, RMSE 2, no spread.
  const MeasureAgreement& rom = find_group(t, "initial", "horizontal").measures[5];
  EXPECT_EQ(rom.measure.name, "rom_index_mcp");
  EXPECT_NEAR(rom.differences.mean_difference, -2.0, 1e-12);
  EXPECT_NEAR(rom.differences.rmse, 2.0, 1e-12);
  EXPECT_NEAR(rom.bland_altman.bias, -2.0, 1e-12);
  EXPECT_NEAR(rom.bland_altman.sd_difference, 0.0, 1e-12);
}

TEST(ReviewAgreement, OneSubjectHasBiasRmseAndRButNoLimits) {
  // S1's three trials, differences 1, 3, 5: what needs no second subject is there.
  const std::vector<AgreementTrial> trials = {paired("S1", "initial", "horizontal", 51, 50),
                                              paired("S1", "initial", "horizontal", 63, 60),
                                              paired("S1", "initial", "horizontal", 70, 65)};
  const AgreementTable t = agreement_table(trials);
  const MeasureAgreement& m = find_group(t, "all", "all").measures[0];
  EXPECT_EQ(m.n_trials, 3u);
  EXPECT_EQ(m.n_subjects, 1u);
  EXPECT_NEAR(m.bland_altman.bias, 3.0, 1e-12);
  EXPECT_NEAR(m.differences.rmse, std::sqrt(35.0 / 3.0), 1e-12);
  const std::vector<double> lmc = {51, 63, 70}, vicon = {50, 60, 65};
  EXPECT_NEAR(m.pearson.r, pearson(lmc, vicon).r, 1e-12);
  // The limits need the spread between subjects: missing, and the reason says so.
  EXPECT_TRUE(std::isnan(m.bland_altman.loa_low));
  EXPECT_TRUE(std::isnan(m.bland_altman.loa_high));
  EXPECT_TRUE(std::isnan(m.bland_altman.bias_ci.low));
  EXPECT_NE(m.bland_altman.reason.find("limits of agreement"), std::string::npos) << m.bland_altman.reason;
  // The CSV has the bias and leaves the limits empty.
  const auto rows = csv_rows(agreement_csv(t));
  EXPECT_EQ(column(rows, 1, "ba_bias").substr(0, 3), "3.0");
  EXPECT_EQ(column(rows, 1, "ba_loa_low"), "");
}

TEST(ReviewAgreement, OneTrialPerSubjectUsesTheSimpleForm) {
  const AgreementTable t = agreement_table(study_trials());
  const MeasureAgreement& m = find_group(t, "optimized", "vertical").measures[2];  // middle length
  EXPECT_EQ(m.n_trials, 3u);
  EXPECT_EQ(m.n_subjects, 3u);
  EXPECT_NE(m.bland_altman.method.find("one pair per subject"), std::string::npos) << m.bland_altman.method;
  // d = 1, 2, 6: bias 3, Σ(d − 3)² = 14 → SD √7, Σd² = 41.
  EXPECT_NEAR(m.bland_altman.bias, 3.0, 1e-12);
  EXPECT_NEAR(m.bland_altman.sd_difference, std::sqrt(7.0), 1e-12);
  EXPECT_NEAR(m.differences.rmse, std::sqrt(41.0 / 3.0), 1e-12);
  EXPECT_TRUE(std::isnan(m.bland_altman.within_subject_sd));
}

TEST(ReviewAgreement, NullViconValuesAreSkippedAndCountedNeverZero) {
  std::vector<AgreementTrial> trials = study_trials();
  // S1's second optimized trial has no Vicon thumb length: that pair is skipped, not read as 0 mm,
  // and S1 still has one complete pair in the group, so the simple form still applies.
  nlohmann::json s = trial_json("S1_opt_2", "optimized", "vertical", "index", 90, 88);
  s["vicon"]["finger_mean_mm"][0] = nullptr;
  s["lmc"]["finger_mean_mm"][1] = nullptr;
  trials.push_back(agreement_trial("S1", s));
  trials.push_back(agreement_trial("S5", trial_json("no_vicon", "optimized", "vertical", "index", 70, 80, false)));
  const AgreementTable t = agreement_table(trials);
  EXPECT_EQ(t.trials, 11u);
  EXPECT_EQ(t.trials_without_vicon, 1u);
  const AgreementGroup& g = find_group(t, "optimized", "vertical");
  EXPECT_EQ(g.n_trials, 4u);
  const MeasureAgreement& thumb = g.measures[0];
  EXPECT_EQ(thumb.n_trials, 3u);
  EXPECT_EQ(thumb.n_skipped, 1u);
  EXPECT_EQ(thumb.differences.n_skipped, 1u);
  EXPECT_EQ(thumb.bland_altman.n_skipped, 1u);
  EXPECT_NE(thumb.bland_altman.method.find("one pair per subject"), std::string::npos);
  EXPECT_NEAR(thumb.bland_altman.bias, 3.0, 1e-12);  // 1, 2, 6 as without the trial
  EXPECT_EQ(thumb.points.size(), 3u);
  // A missing LMC value (index finger) is skipped the same way.
  EXPECT_EQ(g.measures[1].n_skipped, 1u);
  EXPECT_NEAR(g.measures[1].bland_altman.bias, 3.0, 1e-12);
  // The middle finger has all four pairs; S1 now has two, so the repeated form applies.
  EXPECT_EQ(g.measures[2].n_trials, 4u);
  EXPECT_NE(g.measures[2].bland_altman.method.find("2007"), std::string::npos);
}

TEST(ReviewAgreement, GroupsByLayoutAndPoseThenAll) {
  std::vector<AgreementTrial> trials = study_trials();
  trials.push_back(paired("S1", "initial", "vertical", 60, 60));
  trials.push_back(agreement_trial("S2", trial_json("wrist", "initial", "vertical", "wrist", 60, 61)));
  const AgreementTable t = agreement_table(trials);
  ASSERT_EQ(t.groups.size(), 4u);
  EXPECT_EQ(t.groups[0].layout, "initial");
  EXPECT_EQ(t.groups[0].pose, "horizontal");
  EXPECT_EQ(t.groups[0].n_trials, 6u);
  EXPECT_EQ(t.groups[1].pose, "vertical");
  EXPECT_EQ(t.groups[1].n_trials, 2u);  // motions are pooled within layout × pose
  EXPECT_EQ(t.groups[2].layout, "optimized");
  EXPECT_EQ(t.groups[2].n_trials, 3u);
  EXPECT_EQ(t.groups[3].layout, "all");
  EXPECT_EQ(t.groups[3].pose, "all");
  EXPECT_EQ(t.groups[3].n_trials, 11u);
  EXPECT_EQ(t.groups[3].n_subjects, 3u);
  for (const AgreementGroup& g : t.groups) EXPECT_EQ(g.measures.size(), kAgreementMeasures);
  EXPECT_NE(t.groups[3].measures[0].bland_altman.method.find("2007"), std::string::npos);

  AgreementOptions wrist_only;
  wrist_only.motion = "wrist";
  wrist_only.include_all_group = false;
  const AgreementTable w = agreement_table(trials, wrist_only);
  EXPECT_EQ(w.trials, 1u);
  ASSERT_EQ(w.groups.size(), 1u);
  EXPECT_EQ(w.groups[0].pose, "vertical");
  // One pair: no Bland–Altman, NaN with a reason, not 0.
  EXPECT_FALSE(w.groups[0].measures[0].bland_altman.ok());
  EXPECT_TRUE(std::isnan(w.groups[0].measures[0].bland_altman.bias));
}

TEST(ReviewAgreement, BlandAltmanPointsCarryTheSubject) {
  const AgreementTable t = agreement_table(study_trials());
  const auto& pts = find_group(t, "optimized", "vertical").measures[0].points;
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_EQ(pts[0].subject, "S1");
  EXPECT_DOUBLE_EQ(pts[0].mean, 60.5);
  EXPECT_DOUBLE_EQ(pts[0].difference, 1.0);
  EXPECT_EQ(pts[2].subject, "S3");
  EXPECT_DOUBLE_EQ(pts[2].mean, 63.0);
  EXPECT_DOUBLE_EQ(pts[2].difference, 6.0);
}

TEST(ReviewAgreement, CsvHasOneRowPerGroupAndMeasureAndEmptyCellsForNaN) {
  std::vector<AgreementTrial> trials = study_trials();
  trials.push_back(paired("S1", "initial", "vertical", 60, 61));  // a lone trial: every statistic NaN
  const AgreementTable t = agreement_table(trials);
  const std::string csv = agreement_csv(t);
  const auto rows = csv_rows(csv);
  ASSERT_EQ(rows.size(), 1 + t.groups.size() * kAgreementMeasures);
  for (const auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());
  EXPECT_EQ(csv.find("nan"), std::string::npos);
  // Row 1: initial × horizontal, thumb.
  EXPECT_EQ(column(rows, 1, "layout"), "initial");
  EXPECT_EQ(column(rows, 1, "measure"), "finger_length_thumb");
  EXPECT_EQ(column(rows, 1, "unit"), "mm");
  EXPECT_EQ(column(rows, 1, "n_trials"), "6");
  EXPECT_EQ(column(rows, 1, "ba_bias"), "4.000000");
  EXPECT_EQ(column(rows, 1, "rmse"), "4.434712");  // sqrt(118/6)
  EXPECT_NE(column(rows, 1, "ba_method").find("2007"), std::string::npos);
  EXPECT_EQ(column(rows, 1, "icc_form"), "ICC(2,1)");
  EXPECT_EQ(column(rows, 1, "icc_description"),
            "ICC(2,1): two-way random effects, absolute agreement, single measurement");
  EXPECT_EQ(column(rows, 1, "notes"), "");
  // The lone initial × vertical trial: bias −1 is not computable from one pair, so empty, not 0.
  const std::size_t lone = 1 + kAgreementMeasures;
  EXPECT_EQ(column(rows, lone, "pose"), "vertical");
  EXPECT_EQ(column(rows, lone, "n_trials"), "1");
  EXPECT_EQ(column(rows, lone, "ba_bias"), "");
  EXPECT_EQ(column(rows, lone, "ba_loa_low"), "");
  EXPECT_EQ(column(rows, lone, "pearson_r"), "");
  EXPECT_EQ(column(rows, lone, "icc"), "");
  EXPECT_EQ(column(rows, lone, "rmse"), "");
  EXPECT_NE(column(rows, lone, "notes").find("Bland-Altman"), std::string::npos);
  // The simple form has no within-subject SD: empty.
  EXPECT_EQ(column(rows, 1 + 2 * kAgreementMeasures, "ba_within_subject_sd"), "");
  EXPECT_EQ(column(rows, 1 + 2 * kAgreementMeasures, "layout"), "optimized");
  EXPECT_EQ(column(rows, 1 + 3 * kAgreementMeasures + 5, "unit"), "deg");
}

TEST(ReviewAgreement, JsonWritesNaNAsNull) {
  std::vector<AgreementTrial> trials = {paired("S1", "initial", "vertical", 60, 61)};
  // NaN is held as a NaN number and written as null: read back what a file would hold.
  const nlohmann::json j = nlohmann::json::parse(nlohmann::json(agreement_table(trials)).dump());
  EXPECT_EQ(j["groups"].size(), 2u);
  const auto& m = j["groups"][0]["measures"][0];
  EXPECT_EQ(m["unit"], "mm");
  EXPECT_TRUE(m["bland_altman"]["bias"].is_null());
  EXPECT_EQ(m["icc"]["form"], "ICC(2,1)");
  EXPECT_EQ(m["points"].size(), 1u);
  EXPECT_DOUBLE_EQ(m["points"][0]["difference"].get<double>(), -1.0);
}

}  // namespace lmc::agreement_test
