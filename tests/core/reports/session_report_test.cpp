#include <gtest/gtest.h>

#include <cmath>

#include "core/common/number_format.h"
#include "core/reports/session_report.h"
#include "core/results/trial_outputs.h"

namespace lmc {
namespace {

nlohmann::json summary(const std::string& trial, double lmc_len, double vicon_len, double rate,
                       double angle_diff = 0.0) {
  nlohmann::json s;
  s["trial"] = trial;
  s["method"] = "default";
  s["frames"] = 100;
  s["tag"] = {{"layout", "initial"}, {"pose", "horizontal"}, {"motion", "index"}, {"repetition", 1}};
  s["lmc"] = {{"finger_mean_mm", {lmc_len, lmc_len, lmc_len, lmc_len, lmc_len}},
              {"angle_rom_deg", {10, 20, 30, 40, 50, 60}}};
  s["vicon"] = {{"finger_mean_mm", {vicon_len, vicon_len, vicon_len, vicon_len, vicon_len}},
                {"angle_rom_deg", {12, 20, 30, 40, 50, 60}}};
  s["visibility"] = nlohmann::json::array({{{"device", "LMC1"}, {"rate", {rate, rate, rate, rate, rate}}}});
  s["comparison"] = {{"angle_diff_mean_deg", {angle_diff, angle_diff, angle_diff, angle_diff, angle_diff, angle_diff}}};
  return s;
}

TEST(SessionReport, AggregatesMeanAndSdPerGroup) {
  const MeanSd m = mean_sd({1.0, 2.0, 3.0, kNaN});
  EXPECT_DOUBLE_EQ(m.mean, 2.0);
  EXPECT_DOUBLE_EQ(m.sd, 1.0);
  EXPECT_EQ(m.n, 3);

  const SessionReport r = build_session_report(
      {{"S1", summary("Naiv_Index101", 70, 80, 1.0, 20.0)}, {"S2", summary("Naiv_Index101", 74, 80, -1.0, 30.0)}});
  EXPECT_EQ(r.trials, 2);
  EXPECT_EQ(r.trials_with_vicon, 2);
  // LMC − Vicon: −10 and −6 → −8 ± 2.828.
  EXPECT_NE(r.finger_length_csv.find("initial,horizontal,index,thumb,2,72.000,2.828,80.000,0.000,-8.000,2.828"),
            std::string::npos)
      << r.finger_length_csv;
  // Per-frame angle difference averaged per trial: 20 and 30 → 25 ± 7.071.
  EXPECT_NE(r.joint_angle_csv.find(
                "initial,horizontal,index,index_mcp,2,10.000,0.000,12.000,0.000,-2.000,0.000,25.000,7.071"),
            std::string::npos)
      << r.joint_angle_csv;
  // Visibility: five fingers × two trials, rates 1 and −1 → 0 ± 1.054.
  EXPECT_NE(r.visibility_csv.find("initial,horizontal,index,LMC1,10,0.000,1.054"), std::string::npos)
      << r.visibility_csv;
  EXPECT_NE(r.trials_csv.find("S2,Naiv_Index101,initial,horizontal,index,1,default,100,1"), std::string::npos)
      << r.trials_csv;
  EXPECT_NE(r.markdown.find("-8.00 ± 2.11 mm (n = 10)"), std::string::npos) << r.markdown;
  // Twelve values (6 joints × 2 trials), six 20s and six 30s: 25 ± 5.222.
  EXPECT_NE(
      r.markdown.find(
          "Joint angle difference (per frame, averaged per trial), all joints and trials: 25.00 ± 5.22° (n = 12)"),
      std::string::npos)
      << r.markdown;
  EXPECT_EQ(format_fixed(kNaN, 2), "nan");
}

}  // namespace
}  // namespace lmc
