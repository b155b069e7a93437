#pragma once
// The Devices tab's 3D view while a calibration result waits for Apply or Discard:
// every controller where the layout puts it now, as a see-through ghost outline, beside where the
// calibration puts it, as a solid box in the slot's colour, and a line from the old origin to the
// new one so a correction of a few millimetres still shows. Pure builder (docs/architecture.md): tests
// check it without GL, the view only draws the items.
#include <vector>

#include "core/layout/layout.h"
#include "ui/scene/scene_items.h"

namespace lmc::ui {

// Devices are matched by slot. Per current device i (item id = i, colour = the slot's colour):
// a kBox with role kGhost and kFlagGhost | kFlagTranslucent at the current placement; when the
// calibrated layout has the slot, a kBox with role kDevice at the calibrated placement and, when
// its origin moved, a kSegment with role kGhost from the old origin to the new one.
std::vector<SceneItem> calibration_ghost_items(const Layout& current, const Layout& calibrated);

}  // namespace lmc::ui
