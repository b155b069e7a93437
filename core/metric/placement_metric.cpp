#include "core/metric/placement_metric.h"

namespace lmc {

double placement_metric(std::span<const std::int64_t> c) {
  std::int64_t n = 0;
  for (auto v : c) n += v;
  if (n == 0 || c.empty()) return 0.0;
  const double nd = static_cast<double>(n);
  double m = 0.0;
  double scale = nd;  // N^(i+1)
  for (size_t i = 0; i + 1 < c.size(); ++i) {
    m += static_cast<double>(c[i]) / scale;
    scale *= nd;
  }
  return m;
}

}  // namespace lmc
