#pragma once
// Colours for plot series that people with the common colour-vision deficiencies can tell apart:
// the Okabe-Ito palette (black replaced by a light grey for the dark background).
#include <array>

#include "ui/scene/colour_maps.h"

namespace lmc::ui {

inline constexpr std::array<Rgba, 8> kSeriesPalette = {{
    {0.90f, 0.62f, 0.00f, 1.0f},  // orange
    {0.34f, 0.71f, 0.91f, 1.0f},  // sky blue
    {0.00f, 0.62f, 0.45f, 1.0f},  // bluish green
    {0.94f, 0.89f, 0.26f, 1.0f},  // yellow
    {0.00f, 0.45f, 0.70f, 1.0f},  // blue
    {0.84f, 0.37f, 0.00f, 1.0f},  // vermillion
    {0.80f, 0.47f, 0.65f, 1.0f},  // reddish purple
    {0.80f, 0.80f, 0.80f, 1.0f},  // light grey
}};

inline const Rgba& series_colour(int i) {
  return kSeriesPalette[static_cast<size_t>(i) % kSeriesPalette.size()];
}

}  // namespace lmc::ui
