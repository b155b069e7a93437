#include "ui/scene/calibration_ghosts.h"

#include "ui/scene/device_case.h"
#include "ui/scene/drag_controller.h"

namespace lmc::ui {
namespace {

// Below this the line from old to new origin would be a dot under the box.
constexpr double kMinShownMoveMm = 0.5;

Rgba slot_colour(int index, float alpha) {
  const auto c = device_colour(index);
  return {c[0], c[1], c[2], alpha};
}

SceneItem device_box(const LayoutDevice& d, ItemRole role, int id, Rgba colour, std::uint32_t flags) {
  SceneItem box;
  box.kind = ItemKind::kBox;
  box.role = role;
  box.transform = device_transform(d);
  const DeviceCaseBox case_box = device_case_box(d);
  box.a = case_box.centre_mm;
  box.b = case_box.half_mm;
  box.colour = colour;
  box.id = id;
  box.flags = flags;
  return box;
}

}  // namespace

std::vector<SceneItem> calibration_ghost_items(const Layout& current, const Layout& calibrated) {
  std::vector<SceneItem> out;
  for (int i = 0; i < current.device_count(); ++i) {
    const LayoutDevice& now = current.devices[static_cast<size_t>(i)];
    out.push_back(device_box(now, ItemRole::kGhost, i, slot_colour(i, 0.45F), kFlagGhost | kFlagTranslucent));
    const int j = calibrated.find_slot(now.slot);
    if (j < 0) continue;
    const LayoutDevice& fixed = calibrated.devices[static_cast<size_t>(j)];
    out.push_back(device_box(fixed, ItemRole::kDevice, i, slot_colour(i, 1.0F), kFlagNone));
    const Eigen::Vector3d from = now.to_world(Eigen::Vector3d::Zero());
    const Eigen::Vector3d to = fixed.to_world(Eigen::Vector3d::Zero());
    if ((to - from).norm() >= kMinShownMoveMm) {
      SceneItem move;
      move.kind = ItemKind::kSegment;
      move.role = ItemRole::kGhost;
      move.a = from;
      move.b = to;
      move.colour = slot_colour(i, 0.9F);
      move.id = i;
      move.flags = kFlagGhost;
      out.push_back(move);
    }
  }
  return out;
}

}  // namespace lmc::ui
