// The Layout tab's scene draws each controller as its own model: the case from the model's
// footprint, the pyramid and the near-range outline from the device's own sensor values.
#include <gtest/gtest.h>

#include "core/io/sensor_catalogue_json.h"
#include "ui/model/layout/layout_actions.h"
#include "ui/scene/device_case.h"
#include "ui/scene/drag_controller.h"
#include "ui/scene/scene_items.h"

namespace lmc::ui {
namespace layout_scene_models_test {

// The paper's square as two Leap Motion Controllers (LMC1, LMC2) and two LMC2s (LMC3, LMC4).
Layout mixed_rig() {
  Layout l = default_new_layout();
  set_models_from_list(l, "lmc,lmc,lmc2,lmc2", sensor_catalogue());
  return l;
}

const SceneItem& item_of(const SceneList& s, ItemRole role, ItemKind kind, int id) {
  for (const SceneItem& it : s.items) {
    if (it.role == role && it.kind == kind && it.id == id) return it;
  }
  ADD_FAILURE() << "no item for device " << id;
  return s.items.front();
}

TEST(LayoutSceneModels, EachCaseIsItsModelsBoxHangingBelowTheOrigin) {
  const Layout l = mixed_rig();
  const DeviceCaseBox lmc = device_case_box(l.devices[0]);
  EXPECT_DOUBLE_EQ(lmc.half_mm.x(), 40.0);
  EXPECT_DOUBLE_EQ(lmc.half_mm.y(), 5.65);
  EXPECT_DOUBLE_EQ(lmc.half_mm.z(), 15.0);
  EXPECT_DOUBLE_EQ(lmc.centre_mm.y(), -5.65);
  EXPECT_NEAR(lmc.top_y_mm(), 0.0, 1e-12) << "the origin is the top centre of the case";
  const DeviceCaseBox lmc2 = device_case_box(l.devices[2]);
  EXPECT_DOUBLE_EQ(lmc2.half_mm.x(), 42.0);
  EXPECT_DOUBLE_EQ(lmc2.half_mm.y(), 6.0);
  EXPECT_DOUBLE_EQ(lmc2.half_mm.z(), 10.0);
  EXPECT_DOUBLE_EQ(lmc2.centre_mm.y(), -6.0);

  SceneInputs in;
  in.layout = &l;
  const SceneList s = build_scene(in);
  for (int i = 0; i < 4; ++i) {
    const SceneItem& box = item_of(s, ItemRole::kDevice, ItemKind::kBox, i);
    const DeviceCaseBox expected = device_case_box(l.devices[static_cast<size_t>(i)]);
    EXPECT_EQ(box.b, expected.half_mm) << l.devices[static_cast<size_t>(i)].slot;
    EXPECT_EQ(box.a, expected.centre_mm) << l.devices[static_cast<size_t>(i)].slot;
  }
}

TEST(LayoutSceneModels, EachPyramidUsesItsDevicesOwnValuesOverridesIncluded) {
  Layout l = mixed_rig();
  l.devices[1].sensor.range_mm = 420;  // an override of LMC2's model
  SceneInputs in;
  in.layout = &l;
  const SceneList s = build_scene(in);
  const double expected_range[4] = {600, 420, 1100, 1100};
  const double expected_half_long[4] = {70, 70, 80, 80};
  const double expected_half_short[4] = {60, 60, 80, 80};
  for (int i = 0; i < 4; ++i) {
    const SceneItem& pyr = item_of(s, ItemRole::kPyramid, ItemKind::kPyramid, i);
    EXPECT_DOUBLE_EQ(pyr.size, expected_range[i]) << i;
    EXPECT_DOUBLE_EQ(pyr.b.x(), expected_half_long[i]) << i;
    EXPECT_DOUBLE_EQ(pyr.b.y(), expected_half_short[i]) << i;
  }
  // Edges: 4 from the apex and 4 around the far end, and 4 around the near range (100 mm here).
  size_t lmc3_edges = 0;
  for (const SceneItem& it : s.items)
    lmc3_edges += it.role == ItemRole::kPyramid && it.kind == ItemKind::kSegment && it.id == 2;
  EXPECT_EQ(lmc3_edges, 12u);
  // The study's model has no near range: no outline.
  const Layout study = default_new_layout();
  in.layout = &study;
  size_t study_edges = 0;
  for (const SceneItem& it : build_scene(in).items)
    study_edges += it.role == ItemRole::kPyramid && it.kind == ItemKind::kSegment && it.id == 2;
  EXPECT_EQ(study_edges, 8u);
}

TEST(LayoutSceneModels, PickingFollowsTheCaseOfTheModel) {
  // Seen from the top, a press 12.5 mm in front of the centre (+z) lands on an LMC (30 mm deep)
  // and beside an LMC2 (20 mm deep) at the same pose.
  Layout l = mixed_rig();
  l.devices[0].pose = DevicePose{};
  l.devices[2].pose = DevicePose{};
  OrbitCamera camera;
  camera.set_named_view(NamedView::kTop);
  DeviceLocks only_move;
  only_move.locked[3] = only_move.locked[4] = true;  // no rings in the way
  const double w = 800, h = 600;
  const auto px = camera.project(Eigen::Vector3d(0, 0, 12.5), w, h);
  ASSERT_TRUE(px.has_value());
  EXPECT_EQ(hover_handle(l.devices[0], only_move, camera, px->x(), px->y(), w, h).kind, HandleKind::kMove);
  EXPECT_EQ(hover_handle(l.devices[2], only_move, camera, px->x(), px->y(), w, h).kind, HandleKind::kNone);
  const auto centre = camera.project(Eigen::Vector3d(0, 0, 0), w, h);
  ASSERT_TRUE(centre.has_value());
  EXPECT_EQ(hover_handle(l.devices[2], only_move, camera, centre->x(), centre->y(), w, h).kind, HandleKind::kMove);
}

}  // namespace layout_scene_models_test
}  // namespace lmc::ui
