#pragma once
// The scene as a list of plain items (docs/architecture.md): a pure builder turns the document, the
// current hand frame, caches and selection into boxes, pyramids, bones, joints, lines, heatmap
// cells and labels. The GL renderer draws only this list; tests check the builder without GL
// ("a selected controller gets the selected flag", "a finger seen by three devices is green").
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/hand/hand_frame.h"
#include "core/layout/layout.h"
#include "ui/scene/colour_maps.h"
#include "ui/scene/device_locks.h"
#include "ui/scene/drag_controller.h"
#include "ui/scene/finger_ray.h"
#include "ui/scene/heatmap_grid.h"

namespace lmc::ui {

enum class ItemKind : int {
  kBox,      // oriented box: transform, centre `a`, half extents `b`
  kPyramid,  // viewing pyramid: transform (device→world), range `size`, half angles in `b.x/b.y` (deg)
  kSegment,  // thin line a → b
  kBone,     // solid cylinder a → b with radius `size`
  kJoint,    // sphere at a with radius `size`
  kCell,     // axis-aligned quad on a horizontal plane: corners a (x0, y, z0) and b (x1, y, z1)
};

enum ItemFlags : std::uint32_t {
  kFlagNone = 0,
  kFlagSelected = 1u << 0,
  kFlagHovered = 1u << 1,
  kFlagGhost = 1u << 2,        // an optimiser candidate, drawn see-through
  kFlagTranslucent = 1u << 3,  // drawn after opaque items without depth writes
};

// What an item stands for, so tests and tooltips can find it.
enum class ItemRole : int {
  kTable,
  kAxis,
  kDevice,
  kDeviceUsbMarker,
  kPyramid,
  kHandle,
  kHand,
  kFinger,
  kRay,
  kHeatmap,
  kGhost,
  kSearchBox
};

struct SceneItem {
  ItemKind kind = ItemKind::kSegment;
  ItemRole role = ItemRole::kTable;
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  double size = 0;
  Rgba colour;
  int id = -1;  // device index, digit (0 thumb … 4 pinky) or ray index
  std::uint32_t flags = kFlagNone;
};

struct SceneLabel {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  std::string text;
  Rgba colour;
  bool emphasised = false;
};

struct SceneInputs {
  const Layout* layout = nullptr;
  const std::vector<DeviceLocks>* locks = nullptr;
  int selected = -1;
  int hovered = -1;
  HandleKind hovered_handle = HandleKind::kNone;
  HandleKind active_handle = HandleKind::kNone;
  const HandFrame* hand = nullptr;  // world frame; null = no hand
  // Devices seeing each finger in this frame (−1 = unknown: drawn neutral grey).
  std::array<int, kNumDigits> finger_seen_count{-1, -1, -1, -1, -1};
  const Layout* ghost = nullptr;  // optimiser's best-so-far
  const std::vector<FingerRay>* rays = nullptr;
  const HeatmapGrid* heatmap = nullptr;
  ColourRange heatmap_range;
  bool show_pyramids = true;
  // Where the optimiser may put controllers (x and z bounds: x_lo, x_hi, z_lo, z_hi, mm), drawn
  // as a rectangle on the table while the Optimiser panel is open; null = not drawn.
  const std::array<double, 4>* search_box = nullptr;
  double table_half_extent_mm = 400;
  double grid_step_mm = 50;
};

struct SceneList {
  std::vector<SceneItem> items;
  std::vector<SceneLabel> labels;
  Eigen::Vector3d bounds_lo = Eigen::Vector3d::Zero(), bounds_hi = Eigen::Vector3d::Zero();

  size_t count(ItemRole role) const;
};

SceneList build_scene(const SceneInputs& in);

// A controller's device-to-world transform as drawn: the pose, then the offset (layout.h).
Eigen::Isometry3d device_transform(const LayoutDevice& d);
// The 12 edges of a kBox item in the world frame (for views that draw outlines, not solids).
std::array<std::array<Eigen::Vector3d, 2>, 12> box_edges(const SceneItem& box);
// The corners of a kBox item's top face (+y of its own frame: a controller's glass), in order
// around the face, world frame.
std::array<Eigen::Vector3d, 4> box_top_face(const SceneItem& box);

// The four far corners of a viewing pyramid (world), each at `range_mm` from the apex along its edge.
std::array<Eigen::Vector3d, 4> pyramid_corners(const Eigen::Isometry3d& device_to_world, double range_mm,
                                               double half_long_deg, double half_short_deg);

// The bones drawn for a hand frame (pairs of point indices) and the digit each belongs to
// (−1 for forearm and palm).
struct BoneSpec {
  int from, to, digit;
};
const std::vector<BoneSpec>& hand_bones();

}  // namespace lmc::ui
