// Consensus measures on constructed hands: known lengths and known misalignment give
// known differences from the seeing controllers' median.
#include "core/processing/consensus.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/angles.h"

namespace lmc {
namespace consensus_test {

// A hand whose every point sits on a straight line along x from the origin, spaced so that each
// segment of every finger is `segment_mm` long, rotated by `turn_deg` about y around the origin.
HandTrack straight_hand(int frames, double segment_mm, double turn_deg = 0) {
  HandTrack t(frames);
  const double a = turn_deg * kRadPerDeg;
  for (int f = 0; f < frames; ++f) {
    for (int p = 0; p < kNumHandPoints; ++p) t.at(f, p) = Vec3(0, 0, 0);
    for (int finger = 0; finger < kNumFingers; ++finger) {
      const auto segments = finger_segments(finger);
      double along = 0;
      for (const int s : segments) {
        const auto pts = segment_points(s);
        const Vec3 from(along * std::cos(a), 10.0 * finger, along * std::sin(a));
        along += segment_mm;
        const Vec3 to(along * std::cos(a), 10.0 * finger, along * std::sin(a));
        t.at(f, pts[0]) = from;
        t.at(f, pts[1]) = to;
      }
    }
  }
  return t;
}

std::vector<std::vector<FingerLabels>> all_seen(int devices, int frames) {
  FingerLabels seen{};
  seen.fill(1);
  return std::vector<std::vector<FingerLabels>>(static_cast<size_t>(devices),
                                                std::vector<FingerLabels>(static_cast<size_t>(frames), seen));
}

TEST(Consensus, TheMedianOfTheSeeingControllersAndTheFusedDifference) {
  std::vector<DeviceTrack> devices = {
      {1, straight_hand(20, 25)}, {2, straight_hand(20, 30)}, {3, straight_hand(20, 40)}};
  auto labels = all_seen(3, 20);
  const HandTrack fused = straight_hand(20, 28);
  const ConsensusReport r = consensus_report(devices, labels, fused);
  const FingerConsensus& index = r.fingers[1];  // three segments
  EXPECT_NEAR(index.finger.median, 90.0, 1e-9);
  EXPECT_NEAR(index.finger.shortest, 75.0, 1e-9);
  EXPECT_NEAR(index.finger.longest, 120.0, 1e-9);
  EXPECT_NEAR(index.finger.fused_minus_median(), 84.0 - 90.0, 1e-9);
  ASSERT_EQ(index.segment.size(), 3u);
  EXPECT_NEAR(index.segment[0].median, 30.0, 1e-9);
  EXPECT_EQ(index.finger.seeing_devices, 3);
  // A controller that never sees the index is left out of its median.
  for (auto& l : labels[2]) l[1] = 0;
  const ConsensusReport without = consensus_report(devices, labels, fused);
  EXPECT_NEAR(without.fingers[1].finger.median, 82.5, 1e-9);
  EXPECT_EQ(without.fingers[1].finger.seeing_devices, 2);
  EXPECT_TRUE(std::isnan(without.fingers[1].finger.device_mean[2]));
  EXPECT_NEAR(without.fingers[0].finger.median, 60.0, 1e-9) << "the thumb is still seen by all three";
}

TEST(Consensus, AveragingTwoControllersTurnedApartShortensTheFingerByTheCosineOfHalfTheTurn) {
  // Two controllers with the same 30 mm segments whose realigned hands are turned 40 degrees apart:
  // their point-by-point average has segments 30·cos(20°) long.
  const HandTrack a = straight_hand(10, 30, -20), b = straight_hand(10, 30, 20);
  HandTrack mean(10);
  for (size_t i = 0; i < mean.points.size(); ++i) mean.points[i] = 0.5 * (a.points[i] + b.points[i]);
  const std::vector<DeviceTrack> devices = {{1, a}, {2, b}};
  const ConsensusReport r = consensus_report(devices, all_seen(2, 10), mean);
  const double expected = 90.0 * std::cos(20.0 * kRadPerDeg);
  EXPECT_NEAR(r.fingers[1].finger.median, 90.0, 1e-9);
  EXPECT_NEAR(r.fingers[1].finger.fused, expected, 1e-9);
  EXPECT_LT(r.fingers[1].finger.fused_minus_median(), -5.0);
  EXPECT_GT(r.fingers[1].point_distance_mm, 0.0);
}

}  // namespace consensus_test
}  // namespace lmc
