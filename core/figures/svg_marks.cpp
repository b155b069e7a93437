#include "core/figures/svg_marks.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include "core/figures/locale_free_number.h"

namespace lmc::svg {
namespace {

constexpr double kFarOutside = 1e5;  // px beyond the plot a coordinate is clamped to

}  // namespace

double Mapper::px(double x) const {
  return std::clamp(plot.x + (x - xr.lo) / (xr.hi - xr.lo) * plot.w, plot.x - kFarOutside, plot.right() + kFarOutside);
}

double Mapper::py(double y) const {
  return std::clamp(plot.bottom() - (y - yr.lo) / (yr.hi - yr.lo) * plot.h, plot.y - kFarOutside,
                    plot.bottom() + kFarOutside);
}

std::string num(double v) {
  return fixed_c(v, 2);
}

std::string hex(Rgb c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

void gap_bands(std::string& out, const Series& s, const Mapper& m) {
  const size_t n = std::min(s.x.size(), s.y.size());
  std::ptrdiff_t last = -1;  // the previous present sample
  bool gap = false;
  for (size_t i = 0; i < n; ++i) {
    const bool present = std::isfinite(s.x[i]) && std::isfinite(s.y[i]);
    if (!present) {
      gap = true;
      continue;
    }
    if (gap && last >= 0) {
      const double a = m.px(s.x[static_cast<size_t>(last)]), b = m.px(s.x[i]);
      out += "<rect class=\"gap\" x=\"" + num(std::min(a, b)) + "\" y=\"" + num(m.plot.y) + "\" width=\"" +
             num(std::abs(b - a)) + "\" height=\"" + num(m.plot.h) + "\" fill=\"#000000\" fill-opacity=\"0.06\"/>\n";
    }
    gap = false;
    last = static_cast<std::ptrdiff_t>(i);
  }
}

void line_pieces(std::string& out, const Series& s, const Mapper& m, Rgb c) {
  const size_t n = std::min(s.x.size(), s.y.size());
  std::string d;
  size_t count = 0;
  double lone_x = 0, lone_y = 0;
  const auto flush = [&] {
    if (count >= 2)
      out += "<path class=\"line\" d=\"" + d + "\" fill=\"none\" stroke=\"" + hex(c) +
             "\" stroke-width=\"1.5\" stroke-linejoin=\"round\"/>\n";
    else if (count == 1 && s.style == SeriesStyle::line)
      out += "<circle class=\"lone\" cx=\"" + num(lone_x) + "\" cy=\"" + num(lone_y) + "\" r=\"1.5\" fill=\"" + hex(c) +
             "\"/>\n";
    d.clear();
    count = 0;
  };
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
      flush();
      continue;
    }
    lone_x = m.px(s.x[i]);
    lone_y = m.py(s.y[i]);
    d += (count == 0 ? "M" : " L") + num(lone_x) + "," + num(lone_y);
    ++count;
  }
  flush();
}

void points(std::string& out, const Series& s, const Mapper& m, Rgb c) {
  const size_t n = std::min(s.x.size(), s.y.size());
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
    out += "<circle class=\"point\" cx=\"" + num(m.px(s.x[i])) + "\" cy=\"" + num(m.py(s.y[i])) +
           "\" r=\"2.5\" fill=\"" + hex(c) + "\"/>\n";
  }
}

}  // namespace lmc::svg
