#pragma once
// A live 3-D view of the rig in the world frame: the table grid, the world axes, every
// controller's top face where the layout puts it, and each controller's latest hand in its slot's
// colour. Drag to orbit, wheel to zoom. Shared by the Devices and Record tabs; it only draws what
// it is given (the hands come from live_hands(), ui/model/devices/live_hands.h).
#include <string>
#include <vector>

#include "core/layout/layout.h"
#include "core/processing/online_fusion.h"
#include "ui/model/devices/live_hands.h"
#include "ui/scene/orbit_camera.h"
#include "ui/scene/scene_items.h"

namespace lmc::ui {

// Fills the remaining content region. `id` must be unique in the window. With `fused`, the fused
// hand is drawn thick over the controllers' thin ones, each finger in the colour of how many
// controllers see it now (the Layout tab's seen-by colours: a finger seen by nobody is red).
// With `controllers` (e.g. calibration_ghost_items(), ui/scene/calibration_ghosts.h) those boxes
// are drawn instead of the layout's controllers: ghosts as faint outlines, the others bold, and
// segments as lines; each labelled item gets its slot name from `layout` by item id.
void draw_live_hands_view(const char* id, OrbitCamera& camera, const Layout& layout, const std::vector<LiveHand>& hands,
                          const std::string& caption, const FusedHand* fused = nullptr,
                          const std::vector<SceneItem>* controllers = nullptr);

}  // namespace lmc::ui
