#pragma once
// The visibility bits of what each controller can measure: finger f counts as seen by device d in a
// frame when d sees it (visibility_kernel.h) and none of its four markers lies beyond ±axis_cut_mm
// on an axis of d, where the controller reports the cut value instead of the marker (the paper's
// discussion). These are, per (device, frame), the bits LayoutTally::c_inside_cut is counted from;
// the layout report needs them per controller to say what each one adds inside its cut.
#include <span>

#include "core/layout/layout.h"
#include "core/metric/layout_tally.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc {

// Both tables of a layout from one pass of the kernel (which reports the cut while it has the
// markers in device coordinates): `seen` is compute_visibility's, `inside_cut` the bits above.
// D × N bits each, device-major; parallel over frames, exact for any thread count.
struct VisibilityWithCut {
  VisibilityTable seen;
  VisibilityTable inside_cut;
};
// Each device's axis cut is its own sensor model's (SensorModel::axis_cut_mm).
VisibilityWithCut visibility_with_inside_cut(const Layout& layout, std::span<const PreparedFrame> frames,
                                             double phalanx_radius_mm = 10.0);

// The robust metric's tally of the same layout from those tables, without running the kernel again
// (a finger seen but not inside the cut has a marker beyond it): what tally_layout gives for the
// same views, frames, limits and cut. With `frame_subset`, only those frames.
LayoutTally tally_from_visibility(const VisibilityWithCut& tables, std::span<const DeviceView> views,
                                  std::span<const PreparedFrame> frames, const VisibilityLimits& limits,
                                  std::span<const int> frame_subset = {});
// A mixed rig: device d through limits[d].
LayoutTally tally_from_visibility(const VisibilityWithCut& tables, std::span<const DeviceView> views,
                                  std::span<const PreparedFrame> frames, std::span<const VisibilityLimits> limits,
                                  std::span<const int> frame_subset = {});

}  // namespace lmc
