#include <gtest/gtest.h>

#include <limits>

#include "ui/model/layout/layout_actions.h"
#include "ui/scene/scene_items.h"

namespace lmc::ui {
namespace {

TEST(SceneItems, TheSelectedControllerGetsTheSelectedFlagAndHandles) {
  const Layout l = default_new_layout();
  const std::vector<DeviceLocks> locks(4);
  SceneInputs in;
  in.layout = &l;
  in.locks = &locks;
  in.selected = 2;
  const SceneList s = build_scene(in);
  int selected_boxes = 0;
  for (const SceneItem& it : s.items) {
    if (it.role == ItemRole::kDevice) {
      EXPECT_EQ((it.flags & kFlagSelected) != 0, it.id == 2);
      selected_boxes += (it.flags & kFlagSelected) != 0;
    }
  }
  EXPECT_EQ(selected_boxes, 1);
  EXPECT_EQ(s.count(ItemRole::kDevice), 4u);
  EXPECT_EQ(s.count(ItemRole::kHandle), 128u) << "yaw and tilt rings, 64 segments each";
  // A locked ry removes the yaw ring.
  std::vector<DeviceLocks> locked = locks;
  locked[2].locked[4] = true;
  in.locks = &locked;
  EXPECT_EQ(build_scene(in).count(ItemRole::kHandle), 64u);
}

TEST(SceneItems, AFingerSeenByThreeControllersIsGreenAndByNoneRed) {
  const Layout l = default_new_layout();
  HandFrame hand;
  hand.hand_present = true;
  for (int p = 0; p < kNumHandPoints; ++p) hand.point(p) = Eigen::Vector3d(p, 150, -p);
  SceneInputs in;
  in.layout = &l;
  in.hand = &hand;
  in.finger_seen_count = {3, 0, 1, 2, 4};
  const SceneList s = build_scene(in);
  int fingers = 0;
  for (const SceneItem& it : s.items) {
    if (it.role != ItemRole::kFinger) continue;
    ++fingers;
    EXPECT_EQ(it.colour, seen_count_colour(in.finger_seen_count[static_cast<size_t>(it.id)]));
  }
  EXPECT_GT(fingers, 0);
  EXPECT_EQ(seen_count_colour(3), seen_count_colour(7)) << ">= 3 is one category";
  EXPECT_GT(seen_count_colour(3).g, seen_count_colour(3).r);
  EXPECT_GT(seen_count_colour(0).r, seen_count_colour(0).g);
}

TEST(SceneItems, GhostsRaysAndHeatmapCellsAppearOnlyWhenGiven) {
  const Layout l = default_new_layout();
  SceneInputs in;
  in.layout = &l;
  EXPECT_EQ(build_scene(in).count(ItemRole::kGhost), 0u);
  Layout ghost = l;
  in.ghost = &ghost;
  std::vector<FingerRay> rays(3);
  rays[1].clear = true;
  in.rays = &rays;
  HeatmapGrid g;
  g.nx = g.nz = 4;
  g.value.assign(16, 0.5f);
  g.value[5] = std::numeric_limits<float>::quiet_NaN();  // not computed: no cell
  in.heatmap = &g;
  const SceneList s = build_scene(in);
  EXPECT_EQ(s.count(ItemRole::kGhost), 8u);  // 4 boxes + 4 direction lines
  EXPECT_EQ(s.count(ItemRole::kRay), 3u);
  EXPECT_EQ(s.count(ItemRole::kHeatmap), 15u);
}

}  // namespace
}  // namespace lmc::ui
