#include "ui/model/plot/label_runs.h"

#include <algorithm>

namespace lmc::ui {

std::vector<LabelRun> label_runs(std::span<const double> x, std::span<const std::int8_t> labels, double view_lo,
                                 double view_hi) {
  std::vector<LabelRun> runs;
  const size_t n = std::min(x.size(), labels.size());
  if (n == 0) return runs;
  const auto half_step = [&](size_t i, bool before) {
    if (n == 1) return 0.5;
    if (before) return i > 0 ? (x[i] - x[i - 1]) * 0.5 : (x[1] - x[0]) * 0.5;
    return i + 1 < n ? (x[i + 1] - x[i]) * 0.5 : (x[n - 1] - x[n - 2]) * 0.5;
  };
  size_t start = 0;
  for (size_t i = 1; i <= n; ++i) {
    if (i < n && labels[i] == labels[start]) continue;
    LabelRun r{x[start] - half_step(start, true), x[i - 1] + half_step(i - 1, false), labels[start]};
    if (r.x_to >= view_lo && r.x_from <= view_hi) runs.push_back(r);
    start = i;
  }
  return runs;
}

}  // namespace lmc::ui
