#include "ui/scene/colour_maps.h"

#include <algorithm>
#include <cmath>

namespace lmc::ui {

Rgba seen_count_colour(int devices_seeing) {
  // Red for "nobody sees it" (the metric's worst case), through orange and yellow to green.
  switch (std::clamp(devices_seeing, 0, 3)) {
    case 0: return {0.90f, 0.20f, 0.18f, 1.0f};
    case 1: return {0.98f, 0.55f, 0.12f, 1.0f};
    case 2: return {0.95f, 0.85f, 0.20f, 1.0f};
    default: return {0.25f, 0.80f, 0.35f, 1.0f};
  }
}

std::string seen_count_label(int category) {
  switch (category) {
    case 0: return "seen by none";
    case 1: return "seen by 1";
    case 2: return "seen by 2";
    default: return "seen by 3+";
  }
}

Rgba viridis(double t) {
  // matplotlib's viridis at t = 0, 1/8, ..., 1.
  static constexpr std::array<std::array<float, 3>, 9> kStops{{{0.267f, 0.005f, 0.329f},
                                                               {0.279f, 0.175f, 0.483f},
                                                               {0.230f, 0.322f, 0.546f},
                                                               {0.173f, 0.449f, 0.558f},
                                                               {0.128f, 0.567f, 0.551f},
                                                               {0.153f, 0.683f, 0.501f},
                                                               {0.361f, 0.785f, 0.388f},
                                                               {0.668f, 0.862f, 0.196f},
                                                               {0.993f, 0.906f, 0.144f}}};
  if (!std::isfinite(t)) t = 0;
  t = std::clamp(t, 0.0, 1.0) * 8.0;
  const int i = std::min(static_cast<int>(t), 7);
  const float f = static_cast<float>(t - i);
  const auto& a = kStops[static_cast<size_t>(i)];
  const auto& b = kStops[static_cast<size_t>(i + 1)];
  return {a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f, 1.0f};
}

}  // namespace lmc::ui
