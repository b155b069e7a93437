#include "core/metric/coverage.h"

#include "core/common/error.h"
#include "core/layout/layout.h"
#include "core/metric/placement_metric.h"

namespace lmc {

double Coverage::device_finger_fraction(int device, int finger) const {
  if (frames == 0) return 0.0;
  return static_cast<double>(device_finger_seen[static_cast<size_t>(device)][static_cast<size_t>(finger)]) /
         static_cast<double>(frames);
}

double Coverage::finger_unseen_fraction(int finger) const {
  if (frames == 0) return 0.0;
  return static_cast<double>(finger_unseen[static_cast<size_t>(finger)]) / static_cast<double>(frames);
}

Coverage compute_coverage(std::span<const std::span<const FingerBits>> cols, std::span<const int> subset) {
  if (cols.size() > static_cast<size_t>(kMaxDevices)) throw Error("coverage: at most 8 devices");
  Coverage cov;
  cov.devices = static_cast<int>(cols.size());
  cov.c.assign(cols.size() + 1, 0);
  cov.device_finger_seen.assign(cols.size(), {});
  const size_t n_all = cols.empty() ? 0 : cols[0].size();
  const size_t n = subset.empty() ? n_all : subset.size();
  FingerBits bits[kMaxDevices] = {};
  for (size_t jj = 0; jj < n; ++jj) {
    const size_t j = subset.empty() ? jj : static_cast<size_t>(subset[jj]);
    for (size_t d = 0; d < cols.size(); ++d) {
      bits[d] = cols[d][j];
      for (int k = 0; k < kNumDigits; ++k) {
        if ((bits[d] >> k) & 1) ++cov.device_finger_seen[d][static_cast<size_t>(k)];
      }
    }
    FingerBits any = 0;
    for (size_t d = 0; d < cols.size(); ++d) any |= bits[d];
    for (int k = 0; k < kNumDigits; ++k) {
      if (!((any >> k) & 1)) ++cov.finger_unseen[static_cast<size_t>(k)];
    }
    ++cov.c[static_cast<size_t>(worst_finger_count(bits, cov.devices))];
  }
  cov.frames = static_cast<std::int64_t>(n);
  cov.metric = placement_metric(cov.c);
  return cov;
}

Coverage compute_coverage(const VisibilityTable& table, std::span<const int> subset) {
  std::vector<std::span<const FingerBits>> cols;
  for (int d = 0; d < table.devices; ++d) cols.push_back(table.device_column(d));
  return compute_coverage(std::span<const std::span<const FingerBits>>(cols), subset);
}

namespace {

Coverage empty_coverage(int devices) {
  Coverage c;
  c.devices = devices;
  c.c.assign(static_cast<size_t>(devices) + 1, 0);
  c.device_finger_seen.assign(static_cast<size_t>(devices), {});
  return c;
}

}  // namespace

OrientationCoverage coverage_by_orientation(std::span<const std::span<const FingerBits>> cols,
                                            std::span<const int> horizontal, std::span<const int> vertical) {
  const int devices = static_cast<int>(cols.size());
  OrientationCoverage out;
  out.all = compute_coverage(cols);
  out.horizontal = horizontal.empty() ? empty_coverage(devices) : compute_coverage(cols, horizontal);
  out.vertical = vertical.empty() ? empty_coverage(devices) : compute_coverage(cols, vertical);
  return out;
}

OrientationCoverage coverage_by_orientation(const VisibilityTable& table, std::span<const int> horizontal,
                                            std::span<const int> vertical) {
  std::vector<std::span<const FingerBits>> cols;
  for (int d = 0; d < table.devices; ++d) cols.push_back(table.device_column(d));
  return coverage_by_orientation(std::span<const std::span<const FingerBits>>(cols), horizontal, vertical);
}

}  // namespace lmc
