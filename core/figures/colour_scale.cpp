#include "core/figures/colour_scale.h"

#include <array>
#include <cmath>

namespace lmc {
namespace colour_scale_detail {

// viridis at 0, 1/8, …, 1 (matplotlib's table).
constexpr std::array<Rgb, 9> kViridis = {{{68, 1, 84},
                                          {71, 45, 123},
                                          {59, 82, 139},
                                          {44, 114, 142},
                                          {33, 145, 140},
                                          {40, 174, 128},
                                          {94, 201, 98},
                                          {173, 220, 48},
                                          {253, 231, 37}}};

std::uint8_t mix(std::uint8_t a, std::uint8_t b, double f) {
  return static_cast<std::uint8_t>(std::lround(a + (b - a) * f));
}

}  // namespace colour_scale_detail

Rgb sequential_colour(double t) {
  using colour_scale_detail::kViridis;
  if (!(t > 0)) return kViridis.front();  // NaN lands here too
  if (t >= 1) return kViridis.back();
  const double pos = t * static_cast<double>(kViridis.size() - 1);
  const auto i = static_cast<size_t>(pos);
  const double f = pos - static_cast<double>(i);
  const Rgb a = kViridis[i], b = kViridis[i + 1];
  return {colour_scale_detail::mix(a.r, b.r, f), colour_scale_detail::mix(a.g, b.g, f),
          colour_scale_detail::mix(a.b, b.b, f)};
}

bool wants_light_text(Rgb c) {
  // Rec. 709 luma on the 8-bit values: viridis crosses it between 0.5 and 0.625, where black
  // and white text read about equally well.
  const double luma = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
  return luma < 128.0;
}

}  // namespace lmc
