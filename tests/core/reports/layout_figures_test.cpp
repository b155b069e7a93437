// The layout report's pictures (issue #15): the top view draws each controller's footprint as a
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
  const figures::Figure fig = layout_top_view(layout, poses, 2);
  ASSERT_EQ(fig.series.size(), layout.devices.size() + 1);
  const auto& lmc1 = fig.series[0];
  EXPECT_EQ(lmc1.name, layout.devices[0].slot);
  ASSERT_GE(lmc1.x.size(), 6u);
  EXPECT_DOUBLE_EQ(lmc1.x[0], lmc1.x[4]);  // the box is closed
  EXPECT_DOUBLE_EQ(lmc1.y[0], lmc1.y[4]);
  EXPECT_TRUE(std::isnan(lmc1.x[5]));      // then a break before the viewing axis
  const auto& palms = fig.series.back();
  EXPECT_EQ(palms.style, figures::SeriesStyle::points);
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
  const figures::Figure fig = pose_redundancy_figure(r);
  ASSERT_EQ(fig.series.size(), 5u);
  EXPECT_EQ(fig.series[4].name, "pinky");
  EXPECT_EQ(fig.series[4].x, (std::vector<double>{1, 2}));
  EXPECT_EQ(fig.series[4].y, (std::vector<double>{0.5, 0.5}));
  ASSERT_EQ(fig.notes.size(), 1u);
  EXPECT_NE(fig.notes[0].find("2 "), std::string::npos);
}

}  // namespace layout_figures_test
}  // namespace lmc
