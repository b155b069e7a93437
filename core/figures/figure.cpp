#include "core/figures/figure.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lmc {
namespace {

constexpr double kMargin = 0.04;  // of the data's span, on each side

struct Extent {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
};

AxisRange finished_range(const Extent& e, const std::optional<AxisRange>& fixed) {
  if (fixed && std::isfinite(fixed->lo) && std::isfinite(fixed->hi) && fixed->hi > fixed->lo) return *fixed;
  if (!(e.hi >= e.lo)) return {0.0, 1.0};
  if (e.hi == e.lo) return {e.lo - 1.0, e.hi + 1.0};
  const double pad = (e.hi - e.lo) * kMargin;
  return {e.lo - pad, e.hi + pad};
}

void add_x(Extent& e, const Figure& f) {
  for (const Series& s : f.series)
    for (const double v : s.x) e.add(v);
}

}  // namespace

Rgb colour_of(const Series& s, std::size_t index) {
  return s.colour ? *s.colour : series_colour(index);
}

AxisRange x_range(const Figure& f) {
  Extent e;
  add_x(e, f);
  return finished_range(e, f.x.range);
}

AxisRange y_range(const Figure& f) {
  Extent e;
  for (const Series& s : f.series)
    for (size_t i = 0; i < s.y.size() && i < s.x.size(); ++i)
      if (std::isfinite(s.x[i])) e.add(s.y[i]);
  for (const ReferenceLine& r : f.references) e.add(r.y);
  return finished_range(e, f.y.range);
}

AxisRange x_range(const FigureGrid& g) {
  Extent e;
  for (const Figure& f : g.panels) add_x(e, f);
  return finished_range(e, g.x.range);
}

}  // namespace lmc
