#pragma once
// Where on the table one controller would help (the Layout tab's heatmap and the
// layout report): for each cell of a grid on the table, the share of pose-set frames in which the
// chosen finger would be visible if the controller's origin stood above that cell (same height and
// orientation), or, in the second mode, the share of frames it would *add* (visible to it and
// seen by no other controller). The workbench draws it under the scene; `lmc evaluate --report`
// writes it as a figure.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <stop_token>
#include <vector>

#include "core/layout/layout.h"
#include "core/visibility/frame_prep.h"

namespace lmc {

enum class HeatmapMode : int {
  kShareVisible = 0,  // share of pose-set frames in which the finger(s) would be visible
  kFramesAdded = 1,   // share of frames it would add: visible to it and seen by no other controller
};

struct PlacementHeatmap {
  int nx = 0, nz = 0;  // cells along x and z
  double x_lo_mm = -400, x_hi_mm = 400;
  double z_lo_mm = -400, z_hi_mm = 400;
  std::vector<float> value;           // nx·nz, row-major by z then x; in [0, 1]
  double data_min = 0, data_max = 0;  // over the finite cells
  int device = -1;                    // layout index of the controller that was swept
  int finger = -1;                    // 0 thumb … 4 pinky, −1 all five
  HeatmapMode mode = HeatmapMode::kShareVisible;

  float at(int ix, int iz) const { return value[static_cast<size_t>(iz * nx + ix)]; }
  double cell_x_mm(int ix) const { return x_lo_mm + (ix + 0.5) * (x_hi_mm - x_lo_mm) / nx; }
  double cell_z_mm(int iz) const { return z_lo_mm + (iz + 0.5) * (z_hi_mm - z_lo_mm) / nz; }
};

struct HeatmapSpec {
  int device = 0;
  int finger = -1;  // 0 thumb … 4 pinky, −1 all five
  HeatmapMode mode = HeatmapMode::kShareVisible;
  int cells = 48;  // per side
  double half_extent_mm = 400;
};

// Sweeps synchronously; nullptr when stopped. `row_done(rows finished)` is called after each row
// of cells. With `frame_subset`, only those frames count (e.g. one palm orientation). A device
// index outside the layout or no frames gives a grid of NaN.
std::shared_ptr<PlacementHeatmap> sweep_placement_heatmap(const Layout& layout, std::span<const PreparedFrame> frames,
                                                          const HeatmapSpec& spec, std::stop_token stop = {},
                                                          const std::function<void(int)>& row_done = {},
                                                          std::span<const int> frame_subset = {});

}  // namespace lmc
