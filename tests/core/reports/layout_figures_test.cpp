// The layout report's pictures: the top view draws each controller's footprint as a
// closed box and its viewing axis as a second piece of the same series, then the palm positions;
// the redundancy figure has one series per finger over the reference poses.
#include <gtest/gtest.h>

#include <cmath>

#include "core/hand/pose_set_generator.h"
#include "core/io/layout_json.h"
#include "core/reports/layout_figures.h"
#include "core/visibility/frame_prep.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace layout_figures_test {  // named: test files share unity batches

TEST(LayoutFigures, TopViewHasFootprintsAxesAndPalms) {
  const Layout layout = load_layout(test::asset_file("layouts/paper-initial.json"));
  PoseSet poses;
  HandFrame f;
  f.hand_present = true;
  for (auto& p : f.points) p = Vec3(0, 0, 0);
  f.points[kPalm] = Vec3(10, 180, -5);
  poses.frames = {f, f, f};
  const Figure fig = layout_top_view(layout, poses, 2);
  ASSERT_EQ(fig.series.size(), layout.devices.size() + 1);
  const auto& lmc1 = fig.series[0];
  EXPECT_EQ(lmc1.name, layout.devices[0].slot);
  ASSERT_GE(lmc1.x.size(), 6u);
  EXPECT_DOUBLE_EQ(lmc1.x[0], lmc1.x[4]);  // the box is closed
  EXPECT_DOUBLE_EQ(lmc1.y[0], lmc1.y[4]);
  EXPECT_TRUE(std::isnan(lmc1.x[5]));  // then a break before the viewing axis
  const auto& palms = fig.series.back();
  EXPECT_EQ(palms.style, SeriesStyle::points);
  ASSERT_EQ(palms.x.size(), 2u);  // every second of three frames: 0 and 2
  EXPECT_DOUBLE_EQ(palms.x[0], 10);
  EXPECT_DOUBLE_EQ(palms.y[0], -5);
  EXPECT_NE(fig.notes.back().find("180 mm"), std::string::npos);
}

TEST(LayoutFigures, RedundancyHasAFingerSeriesOverThePoses) {
  LayoutReport r;
  r.layout_name = "x";
  PoseCoverageRow row;
  row.seen_by_two = {0.1, 0.2, 0.3, 0.4, 0.5};
  r.poses = {row, row};
  const Figure fig = pose_redundancy_figure(r);
  ASSERT_EQ(fig.series.size(), 5u);
  EXPECT_EQ(fig.series[4].name, "pinky");
  EXPECT_EQ(fig.series[4].x, (std::vector<double>{1, 2}));
  EXPECT_EQ(fig.series[4].y, (std::vector<double>{0.5, 0.5}));
  ASSERT_EQ(fig.notes.size(), 1u);
  EXPECT_NE(fig.notes[0].find("2 "), std::string::npos);
}

TEST(LayoutFigures, CoverageHeatmapIsFingersByPosesFromTheReportsNumbers) {
  LayoutReport r;
  r.layout_name = "x";
  r.poses_description = "monte-carlo seed=1 frames=30";
  PoseCoverageRow down, left;
  down.frames = 10;
  down.seen_by_one = {1.0, 0.9, 0.8, 0.7, 0.6};
  down.seen_by_two = {0.5, 0.4, 0.3, 0.2, 0.1};
  left.orientation = HandOrientation::kVertical;
  left.motion = HandMotion::kThumbFlexion;
  left.frames = 20;
  left.seen_by_one = {0.6, 0.6, 0.6, 0.6, 0.6};
  r.poses = {down, left};
  const Heatmap h = finger_coverage_heatmap(r);
  EXPECT_EQ(h.rows, (std::vector<std::string>{"thumb", "index", "middle", "ring", "pinky"}));
  EXPECT_EQ(h.columns, (std::vector<std::string>{"open hand", "thumb flexion"}));
  EXPECT_EQ(h.column_groups, (std::vector<std::string>{"palm down", "palm left"}));
  ASSERT_EQ(h.panels.size(), 2u);
  EXPECT_DOUBLE_EQ(h.at(0, 1, 0), 0.9);  // index, palm down open hand, seen by 1+
  EXPECT_DOUBLE_EQ(h.at(1, 4, 0), 0.1);  // pinky, seen by 2+
  EXPECT_DOUBLE_EQ(h.at(1, 4, 1), 0.0);
  EXPECT_FALSE(h.scale_label.empty());
  std::string notes;
  for (const auto& n : h.notes) notes += n + " ";
  EXPECT_NE(notes.find("10–20 frames a pose"), std::string::npos) << notes;
  EXPECT_NE(notes.find("monte-carlo seed=1"), std::string::npos) << notes;
}

}  // namespace layout_figures_test
}  // namespace lmc
