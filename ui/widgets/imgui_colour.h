#pragma once
// Our colour type (ui/scene/colour_maps.h) as ImGui's packed colour: one conversion for every
// panel.
#include <imgui.h>

#include "ui/scene/colour_maps.h"

namespace lmc::ui {

inline ImU32 to_u32(const Rgba& c) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a));
}

}  // namespace lmc::ui
