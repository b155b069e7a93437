#include "core/metric/robust_metric.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <string>

#include "core/hand/pose_set_generator.h"
#include "core/io/layout_json.h"
#include "core/layout/layout.h"
#include "core/metric/controller_contribution.h"
#include "core/metric/coverage.h"
#include "core/metric/inside_cut_visibility.h"
#include "core/metric/layout_tally.h"
#include "core/metric/placement_metric.h"
#include "core/optimise/search_space.h"
#include "core/visibility/visibility_kernel.h"
#include "tests/support/mc_frames.h"

namespace lmc {
namespace robust_metric_test {

const std::vector<PreparedFrame>& robust_frames() {
  return test::mc_frames(200, 5);
}

std::vector<DeviceView> views_of(const Layout& l) {
  std::vector<DeviceView> v;
  for (const auto& d : l.devices) v.push_back(DeviceView::from_device(d));
  return v;
}

LayoutTally tally_of(const Layout& l) {
  return tally_layout(views_of(l), robust_frames(), make_limits(VisibilityParams::from_sensor(common_sensor(l))));
}

TEST(RobustMetric, WithEveryWeightZeroItIsTheStudysMetricExactly) {
  const Layout l = default_start_layout(4);
  const LayoutTally t = tally_of(l);
  const Coverage cov = compute_coverage(compute_visibility(l, robust_frames()));
  EXPECT_EQ(t.c, cov.c);
  EXPECT_EQ(t.frames, 200);
  const RobustWeights zero = RobustWeights::all_off();
  const RobustTerms r = robust_terms(t, footprint_overlap_share(l), zero);
  EXPECT_EQ(r.total, placement_metric(cov.c));
  EXPECT_EQ(r.metric_m, cov.metric);
}

// M inside the cut: a finger with a marker beyond a controller's axis cut counts as unseen by it.
// It is never below M, equals M when no marker is beyond any cut, and is what paper-optimized-as-
// processed loses most on (two thirds of its seeing pairs have a seen marker beyond the cut).
TEST(RobustMetric, MInsideTheCutCountsOnlyWhatTheControllersCanMeasure) {
  const Layout l = load_layout_or_preset("paper-optimized-as-processed");
  const LayoutTally t = tally_of(l);
  const RobustTerms r = robust_terms(t, footprint_overlap_share(l), RobustWeights{});
  EXPECT_GT(r.axis_cut, 0.5);
  EXPECT_GT(r.metric_m_inside_cut, r.metric_m + 0.2);
  EXPECT_EQ(r.metric_m_inside_cut, placement_metric(t.c_inside_cut));
  const LayoutTally wide =
      tally_layout(views_of(l), robust_frames(), make_limits(VisibilityParams::from_sensor(common_sensor(l))), 1e9);
  EXPECT_EQ(wide.c_inside_cut, wide.c);
  EXPECT_EQ(wide.c, t.c);
  // Its weight adds exactly weight × M_cut to R (the default weight is 1); at 0 it is only reported.
  RobustWeights off;
  off.inside_cut = 0;
  const RobustTerms r0 = robust_terms(t, footprint_overlap_share(l), off);
  EXPECT_EQ(r0.metric_m_inside_cut, r.metric_m_inside_cut);
  EXPECT_DOUBLE_EQ(r.total, r0.total + r.metric_m_inside_cut);
  RobustWeights w;
  w.inside_cut = 2;
  const RobustTerms r2 = robust_terms(t, footprint_overlap_share(l), w);
  EXPECT_DOUBLE_EQ(r2.total, r0.total + 2 * r.metric_m_inside_cut);
  EXPECT_EQ(r2.metric_m_inside_cut, r.metric_m_inside_cut);
  // The reports list it with the others.
  bool listed = false;
  for (const RobustTermInfo& term : robust_term_infos()) listed = listed || std::string(term.key) == "inside_cut";
  EXPECT_TRUE(listed);
}

// What each controller adds inside its cut is counted from the same bits as M_cut: the inside-cut
// table's coverage is the tally's c_inside_cut, a controller sees no more inside its cut than it
// sees, and with a cut no marker reaches the inside-cut figures are the plain ones.
TEST(RobustMetric, EachControllersContributionInsideItsCutComesFromTheBitsMInsideCutCounts) {
  const Layout l = load_layout_or_preset("paper-optimized-as-processed");
  const LayoutTally t = tally_of(l);
  const VisibilityTable table = compute_visibility(l, robust_frames());
  const VisibilityWithCut both = visibility_with_inside_cut(l, robust_frames());
  EXPECT_EQ(both.seen.bits, table.bits);
  const VisibilityTable& inside = both.inside_cut;
  EXPECT_EQ(compute_coverage(inside).c, t.c_inside_cut);
  const std::vector<std::string> slots{"LMC1", "LMC2", "LMC3", "LMC4"};
  const auto with_cut = controller_contributions(table, t, slots, {}, &inside);
  ASSERT_EQ(with_cut.size(), 4u);
  bool some_less = false;
  for (const auto& c : with_cut) {
    EXPECT_LE(c.seeing_inside_cut_share, c.seeing_share) << c.slot;
    some_less = some_less || c.seeing_inside_cut_share < c.seeing_share;
  }
  EXPECT_TRUE(some_less);  // two thirds of its seeing pairs have a seen marker beyond the cut
  Layout uncut = l;
  for (auto& d : uncut.devices) d.sensor.axis_cut_mm = 1e9;
  const VisibilityTable no_cut = visibility_with_inside_cut(uncut, robust_frames()).inside_cut;
  EXPECT_EQ(no_cut.bits, table.bits);
  for (const auto& c : controller_contributions(table, t, slots, {}, &no_cut)) {
    EXPECT_EQ(c.seeing_inside_cut_share, c.seeing_share) << c.slot;
    EXPECT_EQ(c.metric_inside_cut_without, c.metric_without) << c.slot;
    EXPECT_EQ(c.redundant_inside_cut_without, c.redundant_without) << c.slot;
    EXPECT_EQ(c.counts_inside_cut, c.counts) << c.slot;
  }
}

TEST(RobustMetric, TheTallyIsTheSameOnOneOrTwoThreads) {
  Layout l = default_start_layout(4);
  l.devices[3].pose.x_mm = 230;  // some seen markers beyond the cut
  l.devices[1].pose.rx_deg = 25;
  LayoutTally one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = tally_of(l);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = tally_of(l);
  }
  EXPECT_EQ(one.c, two.c);
  EXPECT_EQ(one.device_seeing_frames, two.device_seeing_frames);
  EXPECT_EQ(one.device_sole_frames, two.device_sole_frames);
  EXPECT_EQ(one.device_cut_frames, two.device_cut_frames);
  EXPECT_EQ(one.device_off_centre, two.device_off_centre);
  EXPECT_GT(one.cut_pairs(), 0);
}

TEST(RobustMetric, AParkedControllerCostsAQuarterOfParticipationAndDoesNotCount) {
  Layout l = default_start_layout(4);
  l.devices[0].pose.x_mm = 5000;  // far off the table: sees nothing
  const LayoutTally t = tally_of(l);
  EXPECT_EQ(t.device_seeing_frames[0], 0);
  const RobustTerms r = robust_terms(t, footprint_overlap_share(l), RobustWeights{});
  EXPECT_DOUBLE_EQ(r.participation, 0.25);
  const auto contributions =
      controller_contributions(compute_visibility(l, robust_frames()), t, {"LMC1", "LMC2", "LMC3", "LMC4"});
  ASSERT_EQ(contributions.size(), 4u);
  EXPECT_FALSE(contributions[0].counts);
  EXPECT_EQ(contributions[0].seeing_share, 0.0);
  EXPECT_EQ(contributions[0].off_centre, 1.0);
  for (size_t d = 1; d < 4; ++d) EXPECT_TRUE(contributions[d].counts) << contributions[d].slot;
}

TEST(RobustMetric, SeenMarkersBeyondTheAxisCutCountOnlyForSeenFingers) {
  PreparedFrame f;
  for (int k = 0; k < kNumRayMarkers; ++k) {
    f.mx[static_cast<size_t>(k)] = 0;
    f.my[static_cast<size_t>(k)] = 100;
    f.mz[static_cast<size_t>(k)] = 0;
  }
  const auto tip = static_cast<size_t>(finger_marker(1, 3));  // index fingertip
  f.mx[tip] = 300;
  const DeviceView at_origin = DeviceView::identity();
  EXPECT_TRUE(seen_marker_beyond_cut(f, at_origin, 0b00010, kAxisCutMm));   // index seen
  EXPECT_FALSE(seen_marker_beyond_cut(f, at_origin, 0b00001, kAxisCutMm));  // thumb only
  EXPECT_FALSE(seen_marker_beyond_cut(f, at_origin, 0b00010, 400.0));
  // 300 mm along the world x is 300 mm along the device's z once the device is turned by 90°
  // about y: still beyond the cut.
  DevicePose turned;
  turned.ry_deg = 90;
  EXPECT_TRUE(seen_marker_beyond_cut(f, DeviceView::from_pose(turned), 0b00010, kAxisCutMm));
}

TEST(RobustMetric, OffCentreIsZeroOnTheAxisAndHalfInTheMiddleOfASide) {
  PreparedFrame f;
  const VisibilityLimits lim = make_limits(VisibilityParams{});
  f.cx = 0, f.cy = 150, f.cz = 0;
  EXPECT_DOUBLE_EQ(off_centre_penalty(f, DeviceView::identity(), lim), 0.0);
  f.cx = 150 * lim.tan_half_long;  // on the side plane along x
  EXPECT_NEAR(off_centre_penalty(f, DeviceView::identity(), lim), 0.5, 1e-12);
  f.cz = 150 * lim.tan_half_short;  // the edge
  EXPECT_NEAR(off_centre_penalty(f, DeviceView::identity(), lim), 1.0, 1e-12);
  f.cy = -10;  // below the controller
  EXPECT_EQ(off_centre_penalty(f, DeviceView::identity(), lim), 1.0);
}

TEST(RobustMetric, FootprintsOverlapWhenTheBoxesOnTheTableDo) {
  Layout l = default_start_layout(2);
  l.devices[0].pose = {};
  l.devices[1].pose = {};
  EXPECT_TRUE(footprints_overlap(l.devices[0], l.devices[1]));
  l.devices[1].pose.x_mm = 56;  // 80 mm long: ends at 40 and starts at 16
  EXPECT_TRUE(footprints_overlap(l.devices[0], l.devices[1]));
  l.devices[1].pose.ry_deg = 90;  // now 30 mm wide along x: 41…71
  EXPECT_FALSE(footprints_overlap(l.devices[0], l.devices[1]));
  l.devices[1].pose = {};
  l.devices[1].pose.z_mm = 31;  // 30 mm deep: apart by a millimetre
  EXPECT_FALSE(footprints_overlap(l.devices[0], l.devices[1]));
  EXPECT_EQ(footprint_overlap_share(l), 0.0);
  l.devices[1].offset_mm = {0, 0, -10};  // the calibration offset moves the real controller
  EXPECT_TRUE(footprints_overlap(l.devices[0], l.devices[1]));
  EXPECT_EQ(footprint_overlap_share(l), 1.0);
}

TEST(RobustMetric, MetricNamesParseAndUnknownOnesAreNamed) {
  EXPECT_EQ(placement_metric_from_name("study", "--metric"), PlacementMetricKind::kStudy);
  EXPECT_EQ(placement_metric_from_name("robust", "--metric"), PlacementMetricKind::kRobust);
  try {
    placement_metric_from_name("best", "--metric");
    FAIL();
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("--metric: unknown metric \"best\""), std::string::npos) << e.what();
  }
}

}  // namespace robust_metric_test
}  // namespace lmc
