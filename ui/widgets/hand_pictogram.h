#pragma once
// The motion pictogram: what the subject is asked to do, drawn in a box of the current
// ImGui window — the start pose faint, the end pose as an amber outline, and the animated hand
// solid, with the Layout tab's bones and joints (build_scene's hand items: same radii and colours),
// seen from a fixed angle that shows the motion. The poses come from the model
// (ui/model/record/motion_pictogram.h); this only projects and draws them.
#include <imgui.h>

#include "ui/model/record/motion_pictogram.h"

namespace lmc::ui {

// Fills a `size` box at the cursor (and advances it) on a dark background.
void draw_hand_pictogram(const MotionPictogram& pictogram, ImVec2 size);

}  // namespace lmc::ui
