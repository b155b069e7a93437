#pragma once
// What each controller of a layout contributes ("every controller counts"): how often
// it sees some finger, how often it is the only one seeing some finger, how often a marker it sees
// lies beyond its axis cut, and what the layout loses without it (M and the share of frames with
// every finger seen by ≥ 2 controllers, recomputed from the same visibility bits without it).
#include <span>
#include <string>
#include <vector>

#include "core/metric/layout_tally.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc {

struct ControllerContribution {
  std::string slot;
  double seeing_share = 0;       // frames in which it sees ≥ 1 finger
  double sole_share = 0;         // frames in which it alone sees some finger
  double cut_share = 0;          // of its seeing frames, those with a seen marker beyond the axis cut
  double off_centre = 0;         // mean off-centre of the palm in its pyramid over its seeing frames
  double metric_without = 0;     // M of the layout without it
  double redundant_without = 0;  // share of frames with every finger seen by ≥ 2 controllers, without it
  // The layout is measurably worse without it: M rises or the ≥ 2 share falls.
  bool counts = false;
  // The same four, counting only what it can measure (a finger with a marker beyond its axis cut is
  // unseen by it; inside_cut_visibility.h). Filled when controller_contributions is given that table.
  double seeing_inside_cut_share = 0;
  double metric_inside_cut_without = 0;
  double redundant_inside_cut_without = 0;
  bool counts_inside_cut = false;
};

// Share of frames whose worst-covered finger is seen by ≥ 2 devices (S2 of robust_metric.h).
double redundant_share(std::span<const std::int64_t> c);

// `table` and `tally` describe the same layout on the same frames (or the same `frame_subset`);
// so does `inside_cut` (inside_cut_visibility) when given.
std::vector<ControllerContribution> controller_contributions(const VisibilityTable& table, const LayoutTally& tally,
                                                             const std::vector<std::string>& slots,
                                                             std::span<const int> frame_subset = {},
                                                             const VisibilityTable* inside_cut = nullptr);

}  // namespace lmc
