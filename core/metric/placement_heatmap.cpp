#include "core/metric/placement_heatmap.h"

#include <algorithm>
#include <limits>

#include "core/visibility/device_view.h"
#include "core/visibility/visibility_kernel.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

std::shared_ptr<PlacementHeatmap> sweep_placement_heatmap(const Layout& layout,
                                                          std::span<const PreparedFrame> all_frames,
                                                          const HeatmapSpec& spec, std::stop_token stop,
                                                          const std::function<void(int)>& row_done,
                                                          std::span<const int> frame_subset) {
  auto grid = std::make_shared<PlacementHeatmap>();
  const int cells = spec.cells;
  grid->nx = grid->nz = cells;
  grid->x_lo_mm = grid->z_lo_mm = -spec.half_extent_mm;
  grid->x_hi_mm = grid->z_hi_mm = spec.half_extent_mm;
  grid->device = spec.device;
  grid->finger = spec.finger;
  grid->mode = spec.mode;
  grid->value.assign(static_cast<size_t>(cells) * static_cast<size_t>(cells), std::numeric_limits<float>::quiet_NaN());
  if (spec.device < 0 || spec.device >= layout.device_count()) return grid;
  std::vector<PreparedFrame> subset_frames;
  std::span<const PreparedFrame> frames = all_frames;
  if (!frame_subset.empty()) {
    subset_frames.reserve(frame_subset.size());
    for (const int j : frame_subset) subset_frames.push_back(all_frames[static_cast<size_t>(j)]);
    frames = subset_frames;
  }
  const size_t n = frames.size();
  if (n == 0) return grid;
  const std::vector<VisibilityLimits> limits = device_limits(layout);

  // Fingers no other controller sees, per frame (only the "added" mode needs them).
  std::vector<FingerBits> missing(n, kAllFingersVisible);
  if (spec.mode == HeatmapMode::kFramesAdded) {
    std::vector<FingerBits> column(n);
    std::vector<FingerBits> others(n, 0);
    for (int d = 0; d < layout.device_count(); ++d) {
      if (d == spec.device) continue;
      device_visibility(DeviceView::from_device(layout.devices[static_cast<size_t>(d)]), frames,
                        limits[static_cast<size_t>(d)], column);
      for (size_t j = 0; j < n; ++j) others[j] |= column[j];
      if (stop.stop_requested()) return nullptr;
    }
    for (size_t j = 0; j < n; ++j) missing[j] = static_cast<FingerBits>(~others[j] & kAllFingersVisible);
  }
  const FingerBits want = spec.finger < 0 ? kAllFingersVisible : static_cast<FingerBits>(1u << spec.finger);

  LayoutDevice dev = layout.devices[static_cast<size_t>(spec.device)];
  double lo = 1.0, hi = 0.0;
  for (int iz = 0; iz < cells; ++iz) {
    if (stop.stop_requested()) return nullptr;
    for (int ix = 0; ix < cells; ++ix) {
      // The device origin (pose + offset) stands over the cell centre.
      dev.pose.x_mm = grid->cell_x_mm(ix) - dev.offset_mm.x();
      dev.pose.z_mm = grid->cell_z_mm(iz) - dev.offset_mm.z();
      const DeviceView view = DeviceView::from_device(dev);
      long long count = 0;
      for (size_t j = 0; j < n; ++j) {
        const FingerBits bits = visible_fingers(frames[j], view, limits[static_cast<size_t>(spec.device)]);
        if (spec.mode == HeatmapMode::kShareVisible) {
          count += (bits & want) == want;
        } else {
          // Added: the wanted fingers that nobody else sees are all seen by this controller
          // (for "all": the frame leaves c_0 thanks to it).
          const FingerBits need = missing[j] & want;
          count += need != 0 && (bits & need) == need;
        }
      }
      const double share = static_cast<double>(count) / static_cast<double>(n);
      grid->value[static_cast<size_t>(iz * cells + ix)] = static_cast<float>(share);
      lo = std::min(lo, share);
      hi = std::max(hi, share);
    }
    if (row_done) row_done(iz + 1);
  }
  grid->data_min = lo;
  grid->data_max = hi;
  return grid;
}

}  // namespace lmc
