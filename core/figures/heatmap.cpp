#include "core/figures/heatmap.h"

#include <cmath>
#include <limits>

namespace lmc {

double Heatmap::at(size_t p, size_t row, size_t column) const {
  constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();
  if (p >= panels.size() || row >= rows.size() || column >= columns.size()) return kMissing;
  const size_t i = row * columns.size() + column;
  const auto& v = panels[p].values;
  return i < v.size() && std::isfinite(v[i]) ? v[i] : kMissing;
}

bool Heatmap::has_missing() const {
  for (size_t p = 0; p < panels.size(); ++p)
    for (size_t r = 0; r < rows.size(); ++r)
      for (size_t c = 0; c < columns.size(); ++c)
        if (std::isnan(at(p, r, c))) return true;
  return false;
}

}  // namespace lmc
