#pragma once
// Evaluates many layouts at once on a pose set, the PSO's inner loop: for each layout, the
// histogram c_0…c_D of "devices that see the worst-covered finger" per frame
// (docs/algorithms/metric.md). Parallel over chunks of frames with oneTBB; the per-chunk integer
// histograms are summed, so the result is identical for any thread count and chunking.
#include <cstddef>
#include <cstdint>
#include <span>
#include <stop_token>
#include <vector>

#include "core/metric/layout_tally.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

// Frames per task: small enough that a chunk's prepared frames stay in the core's L2 cache while
// every layout and device runs over them.
inline constexpr size_t kSwarmChunkFrames = 64;

// A run of consecutive frames, [begin, begin + count), evaluated by one task.
struct FrameRun {
  size_t begin = 0;
  size_t count = 0;
};
// The frames [0, frames) as runs of kSwarmChunkFrames (the last one shorter).
std::vector<FrameRun> chunk_runs(size_t frames);

// `views` holds layouts × devices device views, layout-major. `counts` receives
// layouts × (devices + 1) histograms, layout-major. Returns false (counts unspecified) when `stop`
// was requested before the work finished.
bool worst_finger_histograms(std::span<const DeviceView> views, int layouts, int devices,
                             std::span<const PreparedFrame> frames, const VisibilityLimits& limits,
                             std::span<std::int64_t> counts, std::stop_token stop = {});
// The same on some runs of `frames` only (the pruned search evaluates a pose set in rounds).
bool worst_finger_histograms(std::span<const DeviceView> views, int layouts, int devices,
                             std::span<const PreparedFrame> frames, std::span<const FrameRun> runs,
                             const VisibilityLimits& limits, std::span<std::int64_t> counts, std::stop_token stop = {});
// A mixed rig: slot d of every layout sees through slot_limits[d] (`devices` entries), so a slot
// keeps its model while the search moves it.
bool worst_finger_histograms(std::span<const DeviceView> views, int layouts, int devices,
                             std::span<const PreparedFrame> frames, std::span<const FrameRun> runs,
                             std::span<const VisibilityLimits> slot_limits, std::span<std::int64_t> counts,
                             std::stop_token stop = {});

// The robust metric's inner loop: the full tally of each layout (layout_tally.h) instead of the
// histogram alone. `tallies` holds `layouts` entries, each made for `devices` devices. Exact for
// any thread count (integer sums). Returns false when `stop` was requested before the end.
bool layout_tallies(std::span<const DeviceView> views, int layouts, int devices, std::span<const PreparedFrame> frames,
                    const VisibilityLimits& limits, double axis_cut_mm, std::span<LayoutTally> tallies,
                    std::stop_token stop = {});
bool layout_tallies(std::span<const DeviceView> views, int layouts, int devices, std::span<const PreparedFrame> frames,
                    std::span<const FrameRun> runs, const VisibilityLimits& limits, double axis_cut_mm,
                    std::span<LayoutTally> tallies, std::stop_token stop = {});
// A mixed rig: slot d through slot_limits[d] and its axis cut slot_limits[d].axis_cut_mm.
bool layout_tallies(std::span<const DeviceView> views, int layouts, int devices, std::span<const PreparedFrame> frames,
                    std::span<const FrameRun> runs, std::span<const VisibilityLimits> slot_limits,
                    std::span<LayoutTally> tallies, std::stop_token stop = {});

}  // namespace lmc
