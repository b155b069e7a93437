#include "core/metric/placement_heatmap.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/hand/pose_set_generator.h"
#include "core/metric/coverage.h"
#include "core/optimise/search_space.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc {
namespace placement_heatmap_test {

struct HeatmapPoses {
  PoseSet set;
  std::vector<PreparedFrame> prepared;
};

const HeatmapPoses& heatmap_poses() {
  static const HeatmapPoses p = [] {
    PoseSetSettings s;
    s.frames = 120;
    s.seed = 9;
    HeatmapPoses out;
    out.set = generate_pose_set(HandModel(), s);
    out.prepared = prepare_frames(out.set.frames);
    return out;
  }();
  return p;
}

TEST(PlacementHeatmap, ACellUnderTheControllerIsItsOwnShareOfFramesSeen) {
  Layout l = default_start_layout(2);
  // One cell of a 1 × 1 grid sits at the table centre: put the controller there too.
  l.devices[0].pose.x_mm = 0;
  l.devices[0].pose.z_mm = 0;
  const HeatmapSpec spec{0, 1, HeatmapMode::kShareVisible, 1, 400};
  const auto grid = sweep_placement_heatmap(l, heatmap_poses().prepared, spec);
  ASSERT_TRUE(grid);
  const Coverage cov = compute_coverage(compute_visibility(l, heatmap_poses().prepared));
  EXPECT_FLOAT_EQ(grid->at(0, 0), static_cast<float>(cov.device_finger_fraction(0, 1)));
}

TEST(PlacementHeatmap, AFrameSubsetIsTheSameAsAPoseSetOfThoseFrames) {
  const Layout l = default_start_layout(3);
  const auto& p = heatmap_poses();
  const std::vector<int> vertical = p.set.indices_with(HandOrientation::kVertical);
  ASSERT_FALSE(vertical.empty());
  std::vector<PreparedFrame> only;
  for (const int j : vertical) only.push_back(p.prepared[static_cast<size_t>(j)]);
  const HeatmapSpec spec{1, -1, HeatmapMode::kFramesAdded, 6, 300};
  int rows = 0;
  const auto a = sweep_placement_heatmap(
      l, p.prepared, spec, {}, [&](int r) { rows = r; }, vertical);
  const auto b = sweep_placement_heatmap(l, only, spec);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(rows, 6);
  ASSERT_EQ(a->value.size(), 36u);
  for (size_t i = 0; i < a->value.size(); ++i) EXPECT_EQ(a->value[i], b->value[i]) << i;
  EXPECT_DOUBLE_EQ(a->cell_x_mm(0), -250.0);
}

TEST(PlacementHeatmap, StoppedSweepsReturnNothingAndABadDeviceGivesGaps) {
  const Layout l = default_start_layout(2);
  std::stop_source stop;
  stop.request_stop();
  EXPECT_FALSE(sweep_placement_heatmap(l, heatmap_poses().prepared, HeatmapSpec{}, stop.get_token()));
  const auto none =
      sweep_placement_heatmap(l, heatmap_poses().prepared, HeatmapSpec{5, -1, HeatmapMode::kShareVisible, 2, 400});
  ASSERT_TRUE(none);
  for (const float v : none->value) EXPECT_TRUE(std::isnan(v));
}

TEST(CoverageByOrientation, AnOrientationWithoutFramesIsEmptyNotEverything) {
  const Layout l = default_start_layout(2);
  const auto& p = heatmap_poses();
  const VisibilityTable table = compute_visibility(l, p.prepared);
  const std::vector<int> horizontal = p.set.indices_with(HandOrientation::kHorizontal);
  const OrientationCoverage split = coverage_by_orientation(table, horizontal, {});
  EXPECT_EQ(split.all.frames, 120);
  EXPECT_EQ(split.horizontal.frames, static_cast<std::int64_t>(horizontal.size()));
  EXPECT_EQ(split.vertical.frames, 0);
  EXPECT_EQ(split.vertical.c.size(), 3u);
  EXPECT_EQ(split.vertical.metric, 0.0);
}

}  // namespace placement_heatmap_test
}  // namespace lmc
