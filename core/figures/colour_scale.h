#pragma once
// The sequential colour scale of exported heatmaps: viridis (van der Walt & Smith), which stays
// ordered in lightness for readers with the common colour-vision deficiencies and in greyscale
// print, from dark purple at 0 to yellow at 1. Nine control colours, linear between them: close
// enough to the published table that a reader's eye cannot tell, and no table to ship.
#include <string_view>

#include "core/figures/palette.h"

namespace lmc {

inline constexpr std::string_view kSequentialScaleName = "viridis";

// The colour of t in [0, 1]; t outside is clamped. NaN has no colour (the caller draws "no data")
// and gives the colour of 0.
Rgb sequential_colour(double t);

// Whether text on `background` should be white rather than black to stay readable: true on the
// dark part of the scale.
bool wants_light_text(Rgb background);

}  // namespace lmc
