#pragma once
// Our colours as ImGui's packed colour: one conversion for every panel. `alpha` scales the colour's
// own opacity (faint outlines, ghosts).
#include <imgui.h>

#include "ui/model/devices/live_hands.h"
#include "ui/scene/colour_maps.h"

namespace lmc::ui {

inline ImU32 to_u32(const Rgba& c, float alpha = 1.0F) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a * alpha));
}

// A controller slot's colour (device_colour: the same in every tab, legend and plot).
inline ImU32 device_colour_u32(int slot_index, float alpha = 1.0F) {
  const auto c = device_colour(slot_index);
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], alpha));
}

}  // namespace lmc::ui
