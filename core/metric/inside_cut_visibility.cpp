#include "core/metric/inside_cut_visibility.h"

#include <tbb/parallel_for.h>

#include <vector>

namespace lmc {

VisibilityWithCut visibility_with_inside_cut(const Layout& layout, std::span<const PreparedFrame> frames,
                                             double phalanx_radius_mm, double axis_cut_mm) {
  std::vector<DeviceView> views;
  views.reserve(layout.devices.size());
  for (const auto& d : layout.devices) views.push_back(DeviceView::from_device(d));
  const VisibilityLimits limits = make_limits(VisibilityParams::from_sensor(layout.sensor, phalanx_radius_mm));
  VisibilityWithCut t;
  for (VisibilityTable* table : {&t.seen, &t.inside_cut}) {
    table->devices = static_cast<int>(views.size());
    table->frames = static_cast<int>(frames.size());
    table->bits.assign(views.size() * frames.size(), 0);
  }
  const size_t n = frames.size();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& r) {
    const std::span<const PreparedFrame> run = frames.subspan(r.begin(), r.size());
    std::vector<FingerBits> cut(r.size());
    for (size_t d = 0; d < views.size(); ++d) {
      const std::span<FingerBits> seen = std::span<FingerBits>(t.seen.bits).subspan(d * n + r.begin(), r.size());
      const std::span<FingerBits> inside = std::span<FingerBits>(t.inside_cut.bits).subspan(d * n + r.begin(), r.size());
      device_visibility_with_cut(views[d], run, limits, axis_cut_mm, seen, cut);
      for (size_t j = 0; j < r.size(); ++j) inside[j] = static_cast<FingerBits>(seen[j] & ~cut[j]);
    }
  });
  return t;
}

}  // namespace lmc
