#include "core/metric/coverage.h"

#include <gtest/gtest.h>

#include "core/metric/placement_metric.h"
#include "core/reports/coverage_report.h"

namespace lmc {
namespace {

TEST(PlacementMetric, WeighsUnseenFramesAboveEverything) {
  // N = 10, D = 2: M = c0/N + c1/N².
  const std::vector<std::int64_t> c = {1, 3, 6};
  EXPECT_DOUBLE_EQ(placement_metric(c), 1.0 / 10 + 3.0 / 100);
  const std::vector<std::int64_t> all_seen = {0, 0, 10};
  EXPECT_EQ(placement_metric(all_seen), 0.0);
  // One frame with an unseen finger outweighs all the other frames being seen by one device only.
  const std::vector<std::int64_t> one_unseen = {1, 0, 9};
  const std::vector<std::int64_t> all_single = {0, 9, 1};
  EXPECT_GT(placement_metric(one_unseen), placement_metric(all_single));
  EXPECT_EQ(placement_metric(std::vector<std::int64_t>{}), 0.0);
}

TEST(Coverage, CountsWorstFingerPerFrameAndPerDeviceFinger) {
  // 2 devices × 4 frames.
  VisibilityTable t;
  t.devices = 2;
  t.frames = 4;
  t.bits = {
      0x1F, 0x1F, 0x0F, 0x00,  // device 0
      0x1F, 0x0F, 0x0F, 0x00,  // device 1
  };
  const Coverage c = compute_coverage(t);
  EXPECT_EQ(c.frames, 4);
  // frame 0: every finger seen by 2 → F=2; frame 1: pinky by 1 → 1; frame 2: pinky by 0 → 0; frame 3: 0.
  EXPECT_EQ(c.c, (std::vector<std::int64_t>{2, 1, 1}));
  EXPECT_DOUBLE_EQ(c.metric, 2.0 / 4 + 1.0 / 16);
  EXPECT_EQ(c.device_finger_seen[0][4], 2);
  EXPECT_EQ(c.device_finger_seen[1][4], 1);
  EXPECT_EQ(c.device_finger_seen[1][0], 3);
  EXPECT_EQ(c.finger_unseen[4], 2);
  EXPECT_EQ(c.finger_unseen[0], 1);
  EXPECT_DOUBLE_EQ(c.device_finger_fraction(0, 4), 0.5);
  // A subset: frames 0 and 1 only.
  const std::vector<int> subset = {0, 1};
  const Coverage s = compute_coverage(t, subset);
  EXPECT_EQ(s.c, (std::vector<std::int64_t>{0, 1, 1}));
  EXPECT_DOUBLE_EQ(s.metric, 0.0 + 1.0 / 4);
  // Columns give the same as the table.
  std::vector<std::span<const FingerBits>> cols = {t.device_column(0), t.device_column(1)};
  EXPECT_EQ(compute_coverage(std::span<const std::span<const FingerBits>>(cols)).c, c.c);
}

TEST(Coverage, ReportNamesDevicesAndKeys) {
  VisibilityTable t;
  t.devices = 1;
  t.frames = 2;
  t.bits = {0x1F, 0x1E};
  const Coverage c = compute_coverage(t);
  const auto j = coverage_to_json(c, {"LMC1"});
  EXPECT_EQ(j["c"], nlohmann::json({1, 1}));
  EXPECT_EQ(j["coverage"][0]["slot"], "LMC1");
  EXPECT_DOUBLE_EQ(j["coverage"][0]["thumb"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(j["unseen"]["thumb"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(j["metric"].get<double>(), 0.5);
  const std::string text = format_coverage(c, {"LMC1"});
  EXPECT_NE(text.find("M = 0.5"), std::string::npos) << text;
  EXPECT_NE(text.find("LMC1"), std::string::npos);
  EXPECT_NE(text.find("seen by nobody"), std::string::npos);
}

}  // namespace
}  // namespace lmc
