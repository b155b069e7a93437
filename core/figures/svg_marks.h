#pragma once
// The data-driven marks of one plot in SVG: a line as one <path> per run of present samples,
// points as circles, faint bands over gaps. Apart from the layout around them (svg_writer.cpp)
// because the rule that a missing sample is never drawn lives here. Internal to core/figures.
#include <string>

#include "core/figures/figure.h"

namespace lmc::svg {

struct Box {
  double x = 0, y = 0, w = 0, h = 0;
  double right() const { return x + w; }
  double bottom() const { return y + h; }
};

// Data to pixels for one plot area (SVG y grows downwards).
struct Mapper {
  AxisRange xr, yr;
  Box plot;
  // Pixel of a data value; clamped 1e5 px outside the plot (the clip hides it anyway) so a
  // huge value cannot write a huge number.
  double px(double x) const;
  double py(double y) const;
};

// A coordinate in the document: two decimals, C locale.
std::string num(double v);
// "#rrggbb".
std::string hex(Rgb c);

// A band across the plot's height from the last present sample before each run of missing ones
// to the first present one after it; none at either end of the series.
void gap_bands(std::string& out, const Series& s, const Mapper& m);
// The series' line as one <path> per run of present samples: a missing sample ends a piece, so
// nothing is ever drawn through (or to 0 at) a gap. In `line` style a piece of one sample is a dot.
void line_pieces(std::string& out, const Series& s, const Mapper& m, Rgb c);
// A circle per present sample.
void points(std::string& out, const Series& s, const Mapper& m, Rgb c);

}  // namespace lmc::svg
