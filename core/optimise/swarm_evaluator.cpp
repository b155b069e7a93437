#include "core/optimise/swarm_evaluator.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/layout/layout.h"
#include "core/metric/coverage.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc {
namespace {

void check_runs(std::span<const FrameRun> runs, size_t frames, const char* who) {
  for (const FrameRun& r : runs) {
    if (r.count > kSwarmChunkFrames || r.begin > frames || r.count > frames - r.begin) {
      throw Error(std::string(who) + ": a run of frames lies outside the pose set or exceeds a chunk");
    }
  }
}

}  // namespace

std::vector<FrameRun> chunk_runs(size_t frames) {
  std::vector<FrameRun> runs;
  runs.reserve((frames + kSwarmChunkFrames - 1) / kSwarmChunkFrames);
  for (size_t b = 0; b < frames; b += kSwarmChunkFrames) runs.push_back({b, std::min(kSwarmChunkFrames, frames - b)});
  return runs;
}

bool worst_finger_histograms(std::span<const DeviceView> views, int layouts, int devices,
                             std::span<const PreparedFrame> frames, const VisibilityLimits& limits,
                             std::span<std::int64_t> counts, std::stop_token stop) {
  const std::vector<FrameRun> runs = chunk_runs(frames.size());
  return worst_finger_histograms(views, layouts, devices, frames, runs, limits, counts, stop);
}

bool worst_finger_histograms(std::span<const DeviceView> views, int layouts, int devices,
                             std::span<const PreparedFrame> frames, std::span<const FrameRun> runs,
                             const VisibilityLimits& limits, std::span<std::int64_t> counts, std::stop_token stop) {
  if (devices < 1 || devices > kMaxDevices) throw Error("worst_finger_histograms: inconsistent sizes");
  return worst_finger_histograms(views, layouts, devices, frames, runs,
                                 same_limits(limits, static_cast<size_t>(devices)), counts, stop);
}

bool worst_finger_histograms(std::span<const DeviceView> views, int layouts, int devices,
                             std::span<const PreparedFrame> frames, std::span<const FrameRun> runs,
                             std::span<const VisibilityLimits> slot_limits, std::span<std::int64_t> counts,
                             std::stop_token stop) {
  if (devices < 1 || devices > kMaxDevices || layouts < 0 || slot_limits.size() != static_cast<size_t>(devices) ||
      views.size() != static_cast<size_t>(layouts) * static_cast<size_t>(devices) ||
      counts.size() != static_cast<size_t>(layouts) * static_cast<size_t>(devices + 1)) {
    throw Error("worst_finger_histograms: inconsistent sizes");
  }
  check_runs(runs, frames.size(), "worst_finger_histograms");
  const size_t hist_size = counts.size();
  tbb::enumerable_thread_specific<std::vector<std::int64_t>> local(
      [&] { return std::vector<std::int64_t>(hist_size, 0); });
  const auto nd = static_cast<size_t>(devices);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, runs.size(), 1), [&](const tbb::blocked_range<size_t>& rr) {
    if (stop.stop_requested()) return;
    auto& hist = local.local();
    FingerBits bits[kMaxDevices][kSwarmChunkFrames];
    for (size_t ri = rr.begin(); ri < rr.end(); ++ri) {
      const std::span<const PreparedFrame> run = frames.subspan(runs[ri].begin, runs[ri].count);
      for (int l = 0; l < layouts; ++l) {
        const auto ll = static_cast<size_t>(l);
        // One kernel call per device and chunk: the device's view stays in registers over the
        // chunk's frames (visibility_kernel.h).
        for (size_t d = 0; d < nd; ++d) {
          device_visibility(views[ll * nd + d], run, slot_limits[d], std::span<FingerBits>(bits[d], run.size()));
        }
        std::int64_t* h = hist.data() + ll * (nd + 1);
        for (size_t j = 0; j < run.size(); ++j) {
          FingerBits fb[kMaxDevices];
          for (size_t d = 0; d < nd; ++d) fb[d] = bits[d][j];
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
  const std::vector<FrameRun> runs = chunk_runs(frames.size());
  return layout_tallies(views, layouts, devices, frames, runs, limits, axis_cut_mm, tallies, stop);
}

bool layout_tallies(std::span<const DeviceView> views, int layouts, int devices, std::span<const PreparedFrame> frames,
                    std::span<const FrameRun> runs, const VisibilityLimits& limits, double axis_cut_mm,
                    std::span<LayoutTally> tallies, std::stop_token stop) {
  if (devices < 1 || devices > kMaxDevices) throw Error("layout_tallies: inconsistent sizes");
  return layout_tallies(views, layouts, devices, frames, runs,
                        same_limits(limits, static_cast<size_t>(devices), axis_cut_mm), tallies, stop);
}

bool layout_tallies(std::span<const DeviceView> views, int layouts, int devices, std::span<const PreparedFrame> frames,
                    std::span<const FrameRun> runs, std::span<const VisibilityLimits> slot_limits,
                    std::span<LayoutTally> tallies, std::stop_token stop) {
  if (devices < 1 || devices > kMaxDevices || layouts < 0 || slot_limits.size() != static_cast<size_t>(devices) ||
      views.size() != static_cast<size_t>(layouts) * static_cast<size_t>(devices) ||
      tallies.size() != static_cast<size_t>(layouts)) {
    throw Error("layout_tallies: inconsistent sizes");
  }
  check_runs(runs, frames.size(), "layout_tallies");
  using Tallies = std::vector<LayoutTally>;
  tbb::enumerable_thread_specific<Tallies> local(
      [&] { return Tallies(static_cast<size_t>(layouts), LayoutTally(devices)); });
  const auto nd = static_cast<size_t>(devices);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, runs.size(), 1), [&](const tbb::blocked_range<size_t>& rr) {
    if (stop.stop_requested()) return;
    auto& mine = local.local();
    FingerBits bits[kMaxDevices][kSwarmChunkFrames];
    FingerBits cut[kMaxDevices][kSwarmChunkFrames];
    for (size_t ri = rr.begin(); ri < rr.end(); ++ri) {
      const size_t begin = runs[ri].begin;
      const std::span<const PreparedFrame> run = frames.subspan(begin, runs[ri].count);
      for (int l = 0; l < layouts; ++l) {
        const auto ll = static_cast<size_t>(l);
        const std::span<const DeviceView> layout_views = views.subspan(ll * nd, nd);
        // The kernel decides the axis cut while it has the markers in device coordinates, so the
        // tally does not transform them a second time.
        for (size_t d = 0; d < nd; ++d) {
          device_visibility_with_cut(layout_views[d], run, slot_limits[d], slot_limits[d].axis_cut_mm,
                                     std::span<FingerBits>(bits[d], run.size()),
                                     std::span<FingerBits>(cut[d], run.size()));
        }
        tally_frames(run, layout_views, &bits[0][0], &cut[0][0], kSwarmChunkFrames, slot_limits, mine[ll]);
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
