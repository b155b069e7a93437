#include "core/optimise/swarm_evaluator.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include "core/common/error.h"
#include "core/layout/layout.h"
#include "core/metric/coverage.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc {
namespace {

// Frames per task: small enough that a chunk's prepared frames stay in the core's L2 cache while
// every layout and device runs over them.
constexpr size_t kChunkFrames = 64;

}  // namespace

bool worst_finger_histograms(std::span<const DeviceView> views, int layouts, int devices,
                             std::span<const PreparedFrame> frames, const VisibilityLimits& limits,
                             std::span<std::int64_t> counts, std::stop_token stop) {
  if (devices < 1 || devices > kMaxDevices || layouts < 0 ||
      views.size() != static_cast<size_t>(layouts) * static_cast<size_t>(devices) ||
      counts.size() != static_cast<size_t>(layouts) * static_cast<size_t>(devices + 1)) {
    throw Error("worst_finger_histograms: inconsistent sizes");
  }
  const size_t hist_size = counts.size();
  tbb::enumerable_thread_specific<std::vector<std::int64_t>> local([&] { return std::vector<std::int64_t>(hist_size, 0); });
  const size_t n = frames.size();
  const auto nd = static_cast<size_t>(devices);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kChunkFrames), [&](const tbb::blocked_range<size_t>& r) {
    if (stop.stop_requested()) return;
    auto& hist = local.local();
    FingerBits bits[kMaxDevices][kChunkFrames];
    for (size_t begin = r.begin(); begin < r.end(); begin += kChunkFrames) {
      const size_t end = std::min(r.end(), begin + kChunkFrames);
      for (int l = 0; l < layouts; ++l) {
        const auto ll = static_cast<size_t>(l);
        // One kernel call per device and chunk: the device's view stays in registers over the
        // chunk's frames (visibility_kernel.h).
        for (size_t d = 0; d < nd; ++d) {
          device_visibility(views[ll * nd + d], frames.subspan(begin, end - begin), limits,
                            std::span<FingerBits>(bits[d], end - begin));
        }
        std::int64_t* h = hist.data() + ll * (nd + 1);
        for (size_t j = begin; j < end; ++j) {
          FingerBits fb[kMaxDevices];
          for (size_t d = 0; d < nd; ++d) fb[d] = bits[d][j - begin];
          ++h[static_cast<size_t>(worst_finger_count(fb, devices))];
        }
      }
    }
  });
  if (stop.stop_requested()) return false;
  std::fill(counts.begin(), counts.end(), 0);
  for (const auto& h : local) {
    for (size_t i = 0; i < hist_size; ++i) counts[i] += h[i];
  }
  return true;
}

bool layout_tallies(std::span<const DeviceView> views, int layouts, int devices, std::span<const PreparedFrame> frames,
                    const VisibilityLimits& limits, double axis_cut_mm, std::span<LayoutTally> tallies,
                    std::stop_token stop) {
  if (devices < 1 || devices > kMaxDevices || layouts < 0 ||
      views.size() != static_cast<size_t>(layouts) * static_cast<size_t>(devices) ||
      tallies.size() != static_cast<size_t>(layouts)) {
    throw Error("layout_tallies: inconsistent sizes");
  }
  using Tallies = std::vector<LayoutTally>;
  tbb::enumerable_thread_specific<Tallies> local([&] { return Tallies(static_cast<size_t>(layouts), LayoutTally(devices)); });
  const size_t n = frames.size();
  const auto nd = static_cast<size_t>(devices);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kChunkFrames), [&](const tbb::blocked_range<size_t>& r) {
    if (stop.stop_requested()) return;
    auto& mine = local.local();
    FingerBits bits[kMaxDevices][kChunkFrames];
    FingerBits cut[kMaxDevices][kChunkFrames];
    for (size_t begin = r.begin(); begin < r.end(); begin += kChunkFrames) {
      const size_t end = std::min(r.end(), begin + kChunkFrames);
      for (int l = 0; l < layouts; ++l) {
        const auto ll = static_cast<size_t>(l);
        const std::span<const DeviceView> layout_views = views.subspan(ll * nd, nd);
        // The kernel decides the axis cut while it has the markers in device coordinates, so the
        // tally does not transform them a second time.
        for (size_t d = 0; d < nd; ++d) {
          device_visibility_with_cut(layout_views[d], frames.subspan(begin, end - begin), limits, axis_cut_mm,
                                     std::span<FingerBits>(bits[d], end - begin),
                                     std::span<FingerBits>(cut[d], end - begin));
        }
        for (size_t j = begin; j < end; ++j) {
          FingerBits fb[kMaxDevices], fc[kMaxDevices];
          for (size_t d = 0; d < nd; ++d) {
            fb[d] = bits[d][j - begin];
            fc[d] = cut[d][j - begin];
          }
          tally_frame(frames[j], layout_views, fb, fc, limits, mine[ll]);
        }
      }
    }
  });
  if (stop.stop_requested()) return false;
  for (auto& t : tallies) t = LayoutTally(devices);
  for (const auto& mine : local) {
    for (size_t l = 0; l < tallies.size(); ++l) tallies[l].add(mine[l]);
  }
  return true;
}

}  // namespace lmc
