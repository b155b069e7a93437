#pragma once
// The layout report's pictures, as core figures (core/figures/figure.h) so they are
// written as SVG with the data behind them like every other figure:
//  * a top view of the table: each controller's 80 × 30 mm footprint, the line along which it looks
//    up to the height of the hands, and the palm positions of the pose set (the hand's workspace);
//  * per reference pose, the share of frames in which each finger is seen by two or more
//    controllers (the redundancy a robust layout buys);
//  * the same coverage as a heatmap: fingers × reference poses, one panel for "seen by ≥ 1
//    controller" and one for "≥ 2", from the report's numbers (build_layout_report), never
//    recomputed here.
#include <string>

#include "core/figures/figure.h"
#include "core/figures/heatmap.h"
#include "core/hand/pose_set.h"
#include "core/layout/layout.h"
#include "core/metric/layout_report.h"

namespace lmc {

// At most `max_hand_points` palm positions are drawn (evenly spaced through the set).
Figure layout_top_view(const Layout& layout, const PoseSet& poses, int max_hand_points = 1500);

Figure pose_redundancy_figure(const LayoutReport& report);

// Rows thumb … pinky; a column per reference pose present in the set (at most ten: the poses are
// the study's labels, not the frames), grouped by palm orientation. `poses_description` names the
// pose set in the notes.
Heatmap finger_coverage_heatmap(const LayoutReport& report);

}  // namespace lmc
