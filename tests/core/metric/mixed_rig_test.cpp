// A rig of different controller models: every part of the engine uses each device's own sensor
// model (core/layout/sensor_catalogue.h), and a rig of the study's model behaves exactly as the
// single shared sensor did.
#include <gtest/gtest.h>

#include "core/hand/hand_model.h"
#include "core/hand/reference_poses.h"
#include "core/io/layout_json.h"
#include "core/io/sensor_catalogue_json.h"
#include "core/layout/layout.h"
#include "core/metric/inside_cut_visibility.h"
#include "core/metric/layout_tally.h"
#include "core/optimise/pso.h"
#include "core/optimise/search_space.h"
#include "core/optimise/swarm_evaluator.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_explain.h"
#include "core/visibility/visibility_kernel.h"
#include "core/visibility/visibility_tests.h"
#include "tests/support/build_paths.h"
#include "tests/support/mc_frames.h"

namespace lmc {
namespace {

const SensorCatalogue& catalogue() {
  static const SensorCatalogue c = load_sensor_catalogue(lmc::test::test_assets_dir() / "sensors" / "sensors.json");
  return c;
}

LayoutDevice device(const std::string& slot, const std::string& model, const Eigen::Vector3d& at) {
  LayoutDevice d;
  d.slot = slot;
  set_device_model(d, catalogue().at(model, "test"));
  d.pose.x_mm = at.x();
  d.pose.y_mm = at.y();
  d.pose.z_mm = at.z();
  return d;
}

TEST(MixedRig, AHandBeyondAnLmcsRangeIsSeenByAnLmc2) {
  const HandFrame hand = reference_pose(HandModel(), HandOrientation::kHorizontal, HandMotion::kOpen);
  const Eigen::Vector3d palm = hand.point(kPalm);
  // Both straight below the palm, 800 mm down: beyond the LMC's 600 mm, within the LMC2's 1100 mm.
  Layout l;
  l.name = "far";
  l.devices = {device("LMC1", "lmc", palm - Eigen::Vector3d(0, 800, 0)),
               device("LMC2", "lmc2", palm - Eigen::Vector3d(0, 800, 0))};
  const std::vector<PreparedFrame> frames = {prepare_frame(hand)};
  const VisibilityTable t = compute_visibility(l, frames);
  EXPECT_EQ(t.at(0, 0), 0);
  EXPECT_EQ(t.at(1, 0), kAllFingersVisible);
  const std::vector<VisibilityLimits> lim = device_limits(l);
  EXPECT_EQ(explain_visibility(frames[0], DeviceView::from_device(l.devices[0]), lim[0]).fingers[0].reason,
            HiddenReason::kOutOfRange);
}

TEST(MixedRig, AHandOutsideAnLmcsPyramidIsInsideAnLmc2s) {
  const HandFrame hand = reference_pose(HandModel(), HandOrientation::kHorizontal, HandMotion::kOpen);
  const Eigen::Vector3d palm = hand.point(kPalm);
  // Low and far to the side across the device (its z axis): every marker at |z|/y between about 2
  // and 4.5, beyond the LMC's tan 60° = 1.73, inside the LMC2's tan 80° = 5.67. The LMC's range is
  // overridden to the LMC2's so that only the field of view differs.
  Layout l;
  l.name = "side";
  l.devices = {device("LMC1", "lmc", palm - Eigen::Vector3d(0, 160, 480)),
               device("LMC2", "lmc2", palm - Eigen::Vector3d(0, 160, 480))};
  l.devices[0].sensor.range_mm = 1100;
  ASSERT_EQ(validate_layout(l), "");
  const std::vector<PreparedFrame> frames = {prepare_frame(hand)};
  const VisibilityTable t = compute_visibility(l, frames);
  EXPECT_EQ(t.at(0, 0), 0);
  EXPECT_NE(t.at(1, 0), 0);
  const std::vector<VisibilityLimits> lim = device_limits(l);
  for (int d = 0; d < 2; ++d) {
    const DeviceView view = DeviceView::from_device(l.devices[static_cast<size_t>(d)]);
    const VisibilityExplanation why = explain_visibility(frames[0], view, lim[static_cast<size_t>(d)]);
    EXPECT_EQ(why.bits, visible_fingers(frames[0], view, lim[static_cast<size_t>(d)])) << d;
    if (d == 0) {
      EXPECT_EQ(why.fingers[0].reason, HiddenReason::kOutOfView);
    }
  }
}

TEST(MixedRig, NearLimitHidesWhatIsTooCloseToTrack) {
  const VisibilityLimits study = make_limits(VisibilityParams::from_sensor(catalogue().at("study", "").sensor));
  const VisibilityLimits lmc = make_limits(VisibilityParams::from_sensor(catalogue().at("lmc", "").sensor));
  const DeviceView at_origin = DeviceView::identity();
  EXPECT_EQ(vis::marker_in_view(0, 50, 0, at_origin, study), vis::ViewResult::kInside);
  EXPECT_EQ(vis::marker_in_view(0, 50, 0, at_origin, lmc), vis::ViewResult::kOutOfRange);
  EXPECT_EQ(vis::marker_in_view(0, 150, 0, at_origin, lmc), vis::ViewResult::kInside);
}

TEST(MixedRig, StudyModelRigGivesTheSharedSensorsBitsExactly) {
  const Layout paper = load_layout(lmc::test::test_assets_dir() / "layouts" / "paper-optimized.json");
  const auto& frames = lmc::test::mc_frames(3000, 7);
  std::vector<DeviceView> views;
  for (const auto& d : paper.devices) views.push_back(DeviceView::from_device(d));
  EXPECT_EQ(compute_visibility(paper, frames).bits, compute_visibility(views, frames, VisibilityParams{}).bits);
  const LayoutTally shared = tally_layout(views, frames, make_limits(VisibilityParams{}), kAxisCutMm);
  const LayoutTally per_device = tally_layout(views, frames, device_limits(paper));
  EXPECT_EQ(per_device.c, shared.c);
  EXPECT_EQ(per_device.c_inside_cut, shared.c_inside_cut);
  EXPECT_EQ(per_device.device_off_centre, shared.device_off_centre);
  EXPECT_EQ(per_device.device_cut_frames, shared.device_cut_frames);
}

// Each device of a mixed rig counts exactly as it does in a rig of its own model: the per-device
// parts of the tally do not depend on the other devices' models.
TEST(MixedRig, EachDeviceCountsAsInARigOfItsOwnModel) {
  Layout mixed = load_layout(lmc::test::test_assets_dir() / "layouts" / "paper-optimized.json");
  set_models_from_list(mixed, "lmc2,lmc2,lmc,lmc", catalogue());
  Layout all_lmc2 = mixed, all_lmc = mixed;
  set_all_models(all_lmc2, catalogue().at("lmc2", ""));
  set_all_models(all_lmc, catalogue().at("lmc", ""));
  const auto& frames = lmc::test::mc_frames(3000, 7);
  std::vector<DeviceView> views;
  for (const auto& d : mixed.devices) views.push_back(DeviceView::from_device(d));
  const LayoutTally m = tally_layout(views, frames, device_limits(mixed));
  const LayoutTally a2 = tally_layout(views, frames, device_limits(all_lmc2));
  const LayoutTally a1 = tally_layout(views, frames, device_limits(all_lmc));
  for (size_t d = 0; d < 4; ++d) {
    const LayoutTally& own = d < 2 ? a2 : a1;
    EXPECT_EQ(m.device_seeing_frames[d], own.device_seeing_frames[d]) << d;
    EXPECT_EQ(m.device_cut_frames[d], own.device_cut_frames[d]) << d;
    EXPECT_EQ(m.device_off_centre[d], own.device_off_centre[d]) << d;
  }
  // The LMC2s, wider and longer-sighted, see more than LMCs in the same places: LMC2's slot sees the
  // hand in about a third of the frames as an LMC, in all of them as an LMC2.
  EXPECT_GT(a2.device_seeing_frames[1], 2 * a1.device_seeing_frames[1]);
  // The one-pass report tables and the search's tallies agree with tally_layout on the mixed rig.
  const VisibilityWithCut tables = visibility_with_inside_cut(mixed, frames);
  const LayoutTally from_tables = tally_from_visibility(tables, views, frames, device_limits(mixed));
  EXPECT_EQ(from_tables.c, m.c);
  EXPECT_EQ(from_tables.c_inside_cut, m.c_inside_cut);
  EXPECT_EQ(from_tables.device_off_centre, m.device_off_centre);
  std::vector<LayoutTally> swarm(1, LayoutTally(4));
  ASSERT_TRUE(layout_tallies(views, 1, 4, frames, chunk_runs(frames.size()), device_limits(mixed), swarm));
  EXPECT_EQ(swarm[0].c, m.c);
  EXPECT_EQ(swarm[0].device_cut_frames, m.device_cut_frames);
  EXPECT_EQ(swarm[0].device_off_centre, m.device_off_centre);
}

TEST(MixedRig, SearchKeepsEachSlotsModel) {
  Layout start = default_start_layout(4);
  set_models_from_list(start, "lmc2,lmc2,lmc,lmc", catalogue());
  PsoSettings s;
  s.particles = 4;
  s.iterations = 2;
  s.start_from_layout = true;
  const auto& frames = lmc::test::mc_frames(500, 3);
  const PsoResult r = run_pso(start, table_search_space(), frames, s);
  ASSERT_EQ(r.best_layout.device_count(), 4);
  for (size_t d = 0; d < 4; ++d) {
    EXPECT_EQ(r.best_layout.devices[d].model, start.devices[d].model) << d;
    EXPECT_EQ(r.best_layout.devices[d].sensor, start.devices[d].sensor) << d;
  }
  // Its cost is the mixed rig's, as layout_cost counts it with each device's own model.
  EXPECT_DOUBLE_EQ(r.best_cost, layout_cost(r.best_layout, frames));
}

}  // namespace
}  // namespace lmc
