#include "core/session/protocol.h"
#include "core/session/session_state.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/common/error.h"

namespace lmc {
namespace {

using ::testing::HasSubstr;

TEST(Protocol, StudyPlanHasTheStudysEightyTrialsInBlockOrder) {
  const Protocol p = load_protocol("study");
  EXPECT_EQ(p.name, "study");
  ASSERT_EQ(p.layouts.size(), 2u);
  EXPECT_EQ(p.layouts[0].key, "Naiv");
  EXPECT_EQ(p.layouts[0].layout, "paper-initial");
  EXPECT_EQ(p.layouts[1].layout, "paper-optimized-as-processed");
  const auto plan = plan_trials(p);
  ASSERT_EQ(plan.size(), 80u);
  EXPECT_EQ(plan[0].name, "Naiv_Static101");
  EXPECT_EQ(plan[4].name, "Naiv_Static105");
  EXPECT_EQ(plan[5].name, "Naiv_Index101");
  EXPECT_EQ(plan[19].name, "Naiv_Wrist105");
  EXPECT_EQ(plan[20].name, "Naiv_Static201");
  EXPECT_EQ(plan[20].sim_motion, "vertical/static");
  EXPECT_EQ(plan[40].name, "Opti_Static101");
  EXPECT_EQ(plan[40].layout_key, "Opti");
  EXPECT_EQ(plan[79].name, "Opti_Wrist205");
  EXPECT_EQ(plan[79].sim_motion, "vertical/wrist");
  std::set<std::string> names;
  for (const auto& t : plan) names.insert(t.name);
  EXPECT_EQ(names.size(), 80u);
  const TrialType& index = p.trial_types[static_cast<size_t>(plan[5].trial_type)];
  ASSERT_EQ(index.rom.size(), 1u);
  EXPECT_EQ(index.rom[0].joint, "index_mcp");
  EXPECT_DOUBLE_EQ(index.duration_s, 10.0);
  EXPECT_FALSE(index.subject_cue.empty());
}

TEST(Protocol, QuickPlanIsTwoShortTrials) {
  const auto plan = plan_trials(load_protocol("quick"));
  ASSERT_EQ(plan.size(), 2u);
  EXPECT_EQ(plan[0].name, "Naiv_Static101");
  EXPECT_EQ(plan[1].name, "Naiv_Index101");
  EXPECT_EQ(plan[1].sim_motion, "horizontal/index");
  EXPECT_DOUBLE_EQ(load_protocol("quick").trial_types[0].duration_s, 3.0);
}

TEST(Protocol, CounterbalancedOrderKeepsBlocksAndNamesAndRepeatsForASeed) {
  const Protocol p = load_protocol("study");
  const auto plain = plan_trials(p);
  const auto a = plan_trials(p, 7);
  const auto b = plan_trials(p, 7);
  const auto c = plan_trials(p, 8);
  ASSERT_EQ(a.size(), 80u);
  std::vector<std::string> na, nb, nc, np;
  for (size_t i = 0; i < 80; ++i) {
    na.push_back(a[i].name);
    nb.push_back(b[i].name);
    nc.push_back(c[i].name);
    np.push_back(plain[i].name);
    EXPECT_EQ(a[i].index, static_cast<int>(i));
  }
  EXPECT_EQ(na, nb);
  EXPECT_NE(na, np);
  EXPECT_NE(na, nc);
  // Same trials; each layout's 40 trials stay together; repetitions stay in order.
  auto sorted_a = na, sorted_p = np;
  std::sort(sorted_a.begin(), sorted_a.end());
  std::sort(sorted_p.begin(), sorted_p.end());
  EXPECT_EQ(sorted_a, sorted_p);
  for (size_t i = 0; i < 80; ++i) EXPECT_EQ(a[i].layout_key, a[i / 40 * 40].layout_key);
  for (size_t i = 0; i < 80; i += 5)
    for (int r = 0; r < 5; ++r) EXPECT_EQ(a[i + static_cast<size_t>(r)].repetition, r + 1);
}

nlohmann::json minimal() {
  return {{"format", "lmc-protocol"},
          {"format_version", 1},
          {"name", "t"},
          {"repetitions", 2},
          {"layouts", {{{"key", "Naiv"}, {"layout", "paper-initial"}}}},
          {"poses", {{{"key", "horizontal"}, {"code", 1}}}},
          {"quality", {{"warn_min_rate_hz", 12}}},
          {"trial_types",
           {{{"key", "Index"},
             {"sim_motion", "index"},
             {"duration_s", 4},
             {"operator_cue", "o"},
             {"subject_cue", "s"},
             {"rom", {{{"joint", "index_mcp"}, {"expected_deg", 60}}}},
             {"quality", {{"fail_max_gap_s", 2}}}}}}};
}

TEST(Protocol, QualityThresholdsMergeProtocolThenTrialType) {
  const Protocol p = protocol_from_json(minimal(), "t.json");
  const QualityThresholds& q = p.trial_types[0].quality;
  EXPECT_DOUBLE_EQ(q.warn_min_rate_hz, 12);  // protocol level
  EXPECT_DOUBLE_EQ(q.fail_max_gap_s, 2);     // trial type level
  EXPECT_DOUBLE_EQ(q.fail_min_rate_hz, 5);   // default
  const Protocol back = protocol_from_json(protocol_to_json(p), "copy");
  EXPECT_DOUBLE_EQ(back.trial_types[0].quality.fail_max_gap_s, 2);
  EXPECT_EQ(plan_trials(back)[1].name, "Naiv_Index102");
}

void expect_protocol_error(nlohmann::json j, const std::string& path, const std::string& fragment) {
  try {
    protocol_from_json(j, "bad.json");
    ADD_FAILURE() << "expected an error at " << path;
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("bad.json"));
    EXPECT_EQ(e.where().json_path, path) << e.what();
    EXPECT_THAT(e.what(), HasSubstr(fragment));
  }
}

TEST(Protocol, ErrorsNameTheFileAndTheJsonPath) {
  auto j = minimal();
  j["trial_types"][0]["duration_s"] = -1;
  expect_protocol_error(j, "/trial_types/0/duration_s", "more than 0");
  j = minimal();
  j["trial_types"][0]["rom"][0]["joint"] = "elbow";
  expect_protocol_error(j, "/trial_types/0/rom/0/joint", "unknown joint");
  j = minimal();
  j["trial_types"][0]["duraton_s"] = 3;
  expect_protocol_error(j, "/trial_types/0/duraton_s", "unknown field");
  j = minimal();
  j["repetitions"] = 100;
  expect_protocol_error(j, "/repetitions", "1…99");
  j = minimal();
  j["layouts"][0]["key"] = "../x";
  expect_protocol_error(j, "/layouts/0/key", "layout key has a character");
  j = minimal();
  j["trial_types"][0]["quality"]["warn_max_gap_s"] = 5;
  expect_protocol_error(j, "/trial_types/0/quality", "warn_max_gap_s is above fail_max_gap_s");
  j = minimal();
  j["trial_types"][0]["key"] = std::string(70, 'A');
  expect_protocol_error(j, "/trial_types/0/key", "longer than 64");
}

TEST(Protocol, UnknownNameListsTheShippedOnes) {
  try {
    load_protocol("nonesuch");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("quick"));
    EXPECT_THAT(e.what(), HasSubstr("study"));
  }
}

TEST(Protocol, ShippedNamesListTheAssetsProtocolsSorted) {
  const auto names = shipped_protocol_names();
  ASSERT_GE(names.size(), 2U);
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_NE(std::find(names.begin(), names.end(), "quick"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "study"), names.end());
  for (const auto& n : names) EXPECT_NO_THROW(load_protocol(n)) << n;
}

TEST(Protocol, HandSizeRuleIsTheManifestsOne) {
  EXPECT_EQ(hand_size_problem(186), "");
  EXPECT_EQ(hand_size_problem(30), "");
  EXPECT_NE(hand_size_problem(18.6), "");  // cm typed for mm
  EXPECT_NE(hand_size_problem(0), "");
  EXPECT_NE(hand_size_problem(1860), "");
}

TEST(Protocol, ACalibrationStepIsOptionalValidatedAndRoundTrips) {
  nlohmann::json j = protocol_to_json(load_protocol("quick"));
  EXPECT_FALSE(j.contains("calibration")) << "protocols without the step stay as they were";
  EXPECT_FALSE(protocol_from_json(j, "quick.json").calibration.has_value());
  j["calibration"] = {{"duration_s", 5}, {"subject_cue", "still, please"}};
  const Protocol p = protocol_from_json(j, "quick.json");
  ASSERT_TRUE(p.calibration.has_value());
  EXPECT_DOUBLE_EQ(p.calibration->duration_s, 5.0);
  EXPECT_EQ(p.calibration->subject_cue, "still, please");
  EXPECT_FALSE(p.calibration->operator_cue.empty());
  EXPECT_EQ(protocol_to_json(p), protocol_to_json(protocol_from_json(protocol_to_json(p), "again.json")));
  j["calibration"]["duration_s"] = 0.5;
  try {
    protocol_from_json(j, "quick.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("quick.json"));
    EXPECT_THAT(e.what(), HasSubstr("/calibration/duration_s"));
  }
  j["calibration"] = {{"seconds", 5}};
  EXPECT_THROW(protocol_from_json(j, "quick.json"), Error);
  EXPECT_EQ(calibration_trial_name("Naiv", 1), "Calib_Naiv01");
  EXPECT_EQ(calibration_trial_name("Opti", 12), "Calib_Opti12");
}

}  // namespace
}  // namespace lmc
