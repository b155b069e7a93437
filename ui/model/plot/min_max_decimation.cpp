#include "ui/model/plot/min_max_decimation.h"

#include <algorithm>
#include <cmath>

namespace lmc::ui {

std::vector<PlotColumn> decimate_min_max(std::span<const double> x, std::span<const double> y, double x_lo, double x_hi,
                                         int columns) {
  std::vector<PlotColumn> out(static_cast<size_t>(std::max(columns, 0)));
  if (columns <= 0 || !(x_hi > x_lo) || x.size() != y.size()) return out;
  const size_t begin = static_cast<size_t>(std::lower_bound(x.begin(), x.end(), x_lo) - x.begin());
  // The last sample of a series usually sits exactly on the view's right edge: it belongs in.
  const size_t end = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), x_hi) - x.begin());
  const double width = (x_hi - x_lo) / columns;
  // A NaN between the previous finite sample and the next one breaks the line.
  bool gap_since_data = begin > 0 && !std::isfinite(y[begin - 1]);
  bool any_data_before = false;
  size_t i = begin;
  for (int c = 0; c < columns && i < end; ++c) {
    // The column's samples are one contiguous run of the sorted x: find its end by binary search
    // (cheap next to the run itself), then a tight min/max loop without per-sample bookkeeping.
    const double column_hi = x_lo + (c + 1) * width;
    const size_t stop =
        c + 1 == columns
            ? end
            : static_cast<size_t>(std::lower_bound(x.begin() + static_cast<std::ptrdiff_t>(i),
                                                   x.begin() + static_cast<std::ptrdiff_t>(end), column_hi) -
                                  x.begin());
    if (stop == i) continue;
    PlotColumn& col = out[static_cast<size_t>(c)];
    double mn = INFINITY, mx = -INFINITY;
    size_t first = stop, last = stop;
    int finite = 0;
    for (size_t k = i; k < stop; ++k) {
      const double v = y[k];
      const bool ok = std::isfinite(v);
      finite += ok;
      mn = ok && v < mn ? v : mn;
      mx = ok && v > mx ? v : mx;
    }
    const size_t count = stop - i;
    if (finite > 0) {
      for (first = i; !std::isfinite(y[first]); ++first) {
      }
      for (last = stop - 1; !std::isfinite(y[last]); --last) {
      }
      col.has_data = true;
      col.y_min = static_cast<float>(mn);
      col.y_max = static_cast<float>(mx);
      col.y_first = static_cast<float>(y[first]);
      col.y_last = static_cast<float>(y[last]);
      col.joins_previous = any_data_before && !gap_since_data && first == i;
      // A NaN before the column's first finite sample breaks the join too.
      if (first != i) col.joins_previous = false;
      any_data_before = true;
      gap_since_data = last != stop - 1;
    } else {
      gap_since_data = true;
    }
    col.touches_gap = static_cast<size_t>(finite) != count;
    i = stop;
  }
  return out;
}

}  // namespace lmc::ui
