#pragma once
// A table heatmap: per grid cell on the table plane, a value for the selected controller standing
// at that cell's centre (same height and orientation). Immutable once published by the heatmap
// job, shared with the scene via shared_ptr<const HeatmapGrid>.
#include <cstdint>
#include <vector>

namespace lmc::ui {

enum class HeatmapMode : int {
  kShareVisible = 0,  // share of pose-set frames in which the finger(s) would be visible
  kFramesAdded = 1,   // share of frames it would add: visible to it and seen by no other controller
};

struct HeatmapGrid {
  int nx = 0, nz = 0;                // cells along x and z
  double x_lo_mm = -400, x_hi_mm = 400;
  double z_lo_mm = -400, z_hi_mm = 400;
  std::vector<float> value;          // nx·nz, row-major by z then x; in [0, 1]
  double data_min = 0, data_max = 0; // over the finite cells
  int device = -1;                   // layout index of the controller that was swept
  int finger = -1;                   // 0 thumb … 4 pinky, −1 all five
  HeatmapMode mode = HeatmapMode::kShareVisible;
  bool fine = false;                 // false for the coarse preview pass
  std::uint64_t key = 0;             // the input key the grid was computed for

  float at(int ix, int iz) const { return value[static_cast<size_t>(iz * nx + ix)]; }
  double cell_x_mm(int ix) const { return x_lo_mm + (ix + 0.5) * (x_hi_mm - x_lo_mm) / nx; }
  double cell_z_mm(int iz) const { return z_lo_mm + (iz + 0.5) * (z_hi_mm - z_lo_mm) / nz; }
};

}  // namespace lmc::ui
