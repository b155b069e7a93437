#pragma once
// Colour maps as data with meaning (docs/architecture.md):
// * "devices seeing a finger" (0, 1, 2, ≥3) is categorical: four discrete colours, every one in
//   the legend;
// * shares and "frames added" are magnitudes: a perceptually uniform sequential map (viridis,
//   sampled at 9 stops and interpolated linearly), always shown with a colour bar and numbers.
#include <array>
#include <string>

namespace lmc::ui {

struct Rgba {
  float r = 1, g = 1, b = 1, a = 1;
  bool operator==(const Rgba&) const = default;
};

inline constexpr int kSeenCountCategories = 4;  // 0, 1, 2, ≥3
Rgba seen_count_colour(int devices_seeing);
std::string seen_count_label(int category);  // "0 controllers", "1", "2", "3 or more"

// RGB in 0..1, one distinct colour per controller slot (LMC1 … LMC8), the same in every tab,
// legend and plot.
std::array<float, 3> device_colour(int index);

// t in [0, 1] (clamped) → viridis.
Rgba viridis(double t);

// Maps a value to [0, 1] over a display range kept separate from the data range, so two
// heatmaps can share one scale.
struct ColourRange {
  double lo = 0, hi = 1;
  double normalise(double v) const { return hi > lo ? (v - lo) / (hi - lo) : 0.0; }
};

}  // namespace lmc::ui
