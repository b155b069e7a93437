#include "ui/scene/colour_maps.h"

#include <algorithm>
#include <cmath>

#include "core/figures/colour_scale.h"

namespace lmc::ui {

Rgba seen_count_colour(int devices_seeing) {
  // Red for "nobody sees it" (the metric's worst case), through orange and yellow to green.
  switch (std::clamp(devices_seeing, 0, 3)) {
    case 0:
      return {0.90f, 0.20f, 0.18f, 1.0f};
    case 1:
      return {0.98f, 0.55f, 0.12f, 1.0f};
    case 2:
      return {0.95f, 0.85f, 0.20f, 1.0f};
    default:
      return {0.25f, 0.80f, 0.35f, 1.0f};
  }
}

std::string seen_count_label(int category) {
  switch (category) {
    case 0:
      return "seen by none";
    case 1:
      return "seen by 1";
    case 2:
      return "seen by 2";
    default:
      return "seen by 3+";
  }
}

Rgba viridis(double t) {
  // The project's one viridis (core/figures/colour_scale.h), so the 3D heatmap and the exported
  // report heatmaps show a value in the same colour.
  if (!std::isfinite(t)) t = 0;
  const Rgb c = sequential_colour(t);
  return {static_cast<float>(c.r) / 255.0f, static_cast<float>(c.g) / 255.0f, static_cast<float>(c.b) / 255.0f, 1.0f};
}

std::array<float, 3> device_colour(int index) {
  static const std::array<std::array<float, 3>, 8> colours = {{{0.90F, 0.30F, 0.25F},
                                                               {0.25F, 0.65F, 0.95F},
                                                               {0.35F, 0.80F, 0.35F},
                                                               {0.95F, 0.75F, 0.20F},
                                                               {0.75F, 0.45F, 0.90F},
                                                               {0.20F, 0.85F, 0.80F},
                                                               {0.95F, 0.50F, 0.75F},
                                                               {0.70F, 0.70F, 0.70F}}};
  return colours[static_cast<size_t>(((index % 8) + 8) % 8)];
}

}  // namespace lmc::ui
