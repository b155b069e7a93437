#pragma once
// Series colours that people with the common colour-vision deficiencies can tell apart: the
// Okabe–Ito palette, as 8-bit RGB. In the same order as the workbench's plots
// (ui/model/plot/series_palette.h), so an exported figure colours its series as the screen did;
// black stays last here because exported figures have a white background.
#include <array>
#include <cstddef>
#include <cstdint>

namespace lmc {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

inline constexpr std::array<Rgb, 8> kOkabeIto = {{
    {230, 159, 0},    // orange
    {86, 180, 233},   // sky blue
    {0, 158, 115},    // bluish green
    {240, 228, 66},   // yellow
    {0, 114, 178},    // blue
    {213, 94, 0},     // vermillion
    {204, 121, 167},  // reddish purple
    {0, 0, 0},        // black
}};

// The i-th series' default colour; the palette repeats after eight series.
inline constexpr Rgb series_colour(std::size_t i) {
  return kOkabeIto[i % kOkabeIto.size()];
}

}  // namespace lmc
