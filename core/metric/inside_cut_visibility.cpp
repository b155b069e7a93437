#include "core/metric/inside_cut_visibility.h"

#include <tbb/parallel_for.h>

#include <vector>

#include "core/common/error.h"
#include "core/metric/coverage.h"

namespace lmc {

VisibilityWithCut visibility_with_inside_cut(const Layout& layout, std::span<const PreparedFrame> frames,
                                             double phalanx_radius_mm) {
  std::vector<DeviceView> views;
  views.reserve(layout.devices.size());
  for (const auto& d : layout.devices) views.push_back(DeviceView::from_device(d));
  const std::vector<VisibilityLimits> limits = device_limits(layout, phalanx_radius_mm);
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
      const std::span<FingerBits> inside =
          std::span<FingerBits>(t.inside_cut.bits).subspan(d * n + r.begin(), r.size());
      device_visibility_with_cut(views[d], run, limits[d], limits[d].axis_cut_mm, seen, cut);
      for (size_t j = 0; j < r.size(); ++j) inside[j] = static_cast<FingerBits>(seen[j] & ~cut[j]);
    }
  });
  return t;
}

LayoutTally tally_from_visibility(const VisibilityWithCut& tables, std::span<const DeviceView> views,
                                  std::span<const PreparedFrame> frames, const VisibilityLimits& limits,
                                  std::span<const int> subset) {
  return tally_from_visibility(tables, views, frames, same_limits(limits, views.size()), subset);
}

LayoutTally tally_from_visibility(const VisibilityWithCut& tables, std::span<const DeviceView> views,
                                  std::span<const PreparedFrame> frames, std::span<const VisibilityLimits> limits,
                                  std::span<const int> subset) {
  const int nd = tables.seen.devices;
  if (nd < 1 || nd > kMaxDevices || static_cast<size_t>(nd) != views.size() || limits.size() != views.size() ||
      static_cast<size_t>(tables.seen.frames) != frames.size()) {
    throw Error("tally_from_visibility: the tables are of another layout or pose set");
  }
  LayoutTally tally(nd);
  const auto add = [&](int j) {
    FingerBits seen[kMaxDevices] = {}, cut[kMaxDevices] = {};
    for (int d = 0; d < nd; ++d) {
      seen[d] = tables.seen.at(d, j);
      cut[d] = static_cast<FingerBits>(seen[d] & ~tables.inside_cut.at(d, j));
    }
    tally_frame(frames[static_cast<size_t>(j)], views, seen, cut, limits, tally);
  };
  if (subset.empty()) {
    for (int j = 0; j < tables.seen.frames; ++j) add(j);
  } else {
    for (const int j : subset) add(j);
  }
  return tally;
}

}  // namespace lmc
