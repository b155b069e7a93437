#include "core/review/visibility_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/reports/session_report.h"

namespace lmc::visibility_map_test {

nlohmann::json device_rates(const std::string& device, const std::vector<nlohmann::json>& rates) {
  return {{"device", device}, {"rate", rates}};
}

AgreementTrial visibility_trial(const std::string& subject, const std::string& layout, const std::string& motion,
                                const std::vector<nlohmann::json>& devices) {
  nlohmann::json s;
  s["trial"] = subject + "_" + layout + "_" + motion;
  s["tag"] = {{"layout", layout}, {"pose", "horizontal"}, {"motion", motion}, {"repetition", 1}, {"parsed", true}};
  s["visibility"] = devices;
  return agreement_trial(subject, s);
}

std::vector<AgreementTrial> visibility_trials() {
  const nlohmann::json null;
  return {visibility_trial("S1", "initial", "index",
                           {device_rates("LMC1", {1, 1, 1, 1, 1}), device_rates("LMC2", {0.5, 0.5, 0.5, 0.5, null})}),
          visibility_trial(
              "S2", "initial", "index",
              {device_rates("LMC1", {-1, -1, -1, -1, -1}), device_rates("LMC2", {0.25, 0.25, 0.25, 0.25, 0.25})}),
          visibility_trial("S1", "optimized", "index", {device_rates("LMC1", {0.8, 0.8, 0.8, 0.8, 0.8})}),
          visibility_trial("S1", "initial", "static", {device_rates("LMC3", {0.7, null, null, null, null})})};
}

TEST(ReviewVisibilityMap, MeanOverFingersAndTrialsPerDeviceMotionAndLayout) {
  const VisibilityMap map = visibility_map(visibility_trials());
  ASSERT_EQ(map.cells.size(), 4u);
  const VisibilityCell& a = map.cells[0];
  EXPECT_EQ(a.device, "LMC1");
  EXPECT_EQ(a.motion, "index");
  EXPECT_EQ(a.layout, "initial");
  EXPECT_EQ(a.trials, 2u);
  EXPECT_EQ(a.values, 10);
  EXPECT_EQ(a.never_saw, 5u);
  // −1 counts as a value, as in the paper's 0.05 ± 0.55: five 1s and five −1s → 0 ± sqrt(10/9).
  EXPECT_NEAR(a.rate_mean, 0.0, 1e-12);
  EXPECT_NEAR(a.rate_sd, std::sqrt(10.0 / 9.0), 1e-12);
  EXPECT_EQ(map.cells[1].layout, "optimized");
  EXPECT_NEAR(map.cells[1].rate_mean, 0.8, 1e-12);
  // LMC2: a null rate is skipped, not 0: (4 × 0.5 + 5 × 0.25) / 9.
  const VisibilityCell& b = map.cells[2];
  EXPECT_EQ(b.device, "LMC2");
  EXPECT_EQ(b.values, 9);
  EXPECT_NEAR(b.rate_mean, 3.25 / 9.0, 1e-12);
  const VisibilityCell& c = map.cells[3];
  EXPECT_EQ(c.device, "LMC3");
  EXPECT_EQ(c.motion, "static");
  EXPECT_EQ(c.values, 1);
  EXPECT_TRUE(std::isnan(c.rate_sd));
}

TEST(ReviewVisibilityMap, AgreesWithTheSessionReport) {
  const auto trials = visibility_trials();
  std::vector<ReportInput> inputs;
  for (const auto& t : trials) inputs.push_back({t.subject, t.summary});
  const SessionReport report = build_session_report(inputs);
  // The report's "initial,horizontal,index,LMC1" row is the map's LMC1 × index × initial cell.
  EXPECT_NE(report.visibility_csv.find("initial,horizontal,index,LMC1,10,0.000,1.054"), std::string::npos)
      << report.visibility_csv;
  EXPECT_NE(report.visibility_csv.find("initial,horizontal,index,LMC2,9,0.361,"), std::string::npos)
      << report.visibility_csv;
}

TEST(ReviewVisibilityMap, CsvWritesNaNAsAnEmptyCell) {
  const std::string csv = visibility_map_csv(visibility_map(visibility_trials()));
  EXPECT_EQ(csv.rfind("device,motion,layout,trials,values,never_saw_hand,rate_mean,rate_sd\n", 0), 0u) << csv;
  EXPECT_NE(csv.find("LMC1,index,initial,2,10,5,0.000000,1.054093\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("LMC3,static,initial,1,1,0,0.700000,\n"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("nan"), std::string::npos) << csv;
  const nlohmann::json j = nlohmann::json::parse(nlohmann::json(visibility_map(visibility_trials())).dump());
  EXPECT_TRUE(j["cells"][3]["rate_sd"].is_null());
}

}  // namespace lmc::visibility_map_test
