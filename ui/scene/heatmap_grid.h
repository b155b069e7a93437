#pragma once
// A table heatmap as the workbench holds it: core's PlacementHeatmap (core/metric/placement_heatmap.h,
// the one sweep shared with `lmc evaluate --report`) plus which pass and request it belongs to.
// Immutable once published by the heatmap job, shared with the scene via shared_ptr<const HeatmapGrid>.
#include <cstdint>

#include "core/metric/placement_heatmap.h"

namespace lmc::ui {

struct HeatmapGrid : PlacementHeatmap {
  bool fine = false;      // false for the coarse preview pass
  std::uint64_t key = 0;  // the input key the grid was computed for
};

}  // namespace lmc::ui
