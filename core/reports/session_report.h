#pragma once
// `lmc report`: aggregates processed trials (their <trial>.summary.json files) across trials and
// subjects, grouped by layout × pose × motion (trial_tag.h), as the paper reports them:
//  * finger length LMC and Vicon (per-trial mean), and the difference LMC − Vicon, mean ± SD over
//    trials (the paper quotes Vicon − LMC as a positive number: 24.23 ± 6.35 mm);
//  * range of motion per joint, LMC vs Vicon, and their difference, mean ± SD over trials;
//  * the joint-angle difference LMC − Vicon per frame, averaged per trial, mean ± SD over trials
//    (the paper's 29.49° ± 27.85° is of this kind);
//  * visibility rate per device (mean over fingers and trials, −1 "never saw the hand" included as
//    in the paper's 0.05 ± 0.55), mean ± SD.
// Output: CSV tables plus a Markdown summary.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lmc {

struct ReportInput {
  std::string subject;  // e.g. the session folder name
  nlohmann::json summary;
};

struct SessionReport {
  std::string trials_csv;
  std::string finger_length_csv;
  std::string joint_angle_csv;
  std::string visibility_csv;
  std::string markdown;
  int trials = 0;
  int trials_with_vicon = 0;
};

SessionReport build_session_report(const std::vector<ReportInput>& inputs);

// Mean and sample SD (NaN when empty / one value for SD), skipping NaN.
struct MeanSd {
  double mean;
  double sd;
  int n;
};
MeanSd mean_sd(const std::vector<double>& v);

}  // namespace lmc
