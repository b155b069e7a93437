#pragma once
// The robust placement metric: the study's M first, then tie-breakers with explicit
// weights that make every controller count. Lower is better, like M:
//
//   R = M + w_redundancy · (1 − S2)            S2: share of frames in which every finger is seen by ≥ 2 controllers
//         + w_participation · P                P: mean over controllers of max(0, 0.2 − s_d)/0.2, s_d the share of
//                                                 frames in which controller d sees at least one finger
//         + w_axis_cut · A                     A: share of seeing (controller, frame) pairs with a seen marker
//                                                 beyond ±250 mm on an axis of that controller (the paper's axis cut)
//         + w_centring · C                     C: mean off-centre of the palm in the seeing controllers' pyramids
//                                                 (0 on the viewing axis, 1 on the edge; layout_tally.h)
//         + w_footprint · F                    F: share of controller pairs whose footprints (80 × 30 mm boxes
//                                                 projected on the table) overlap
//         + w_inside_cut · M_cut               M_cut: M when a finger with a marker beyond a controller's axis cut
//                                                 counts as unseen by it (what the controllers can measure)
//
// Each term is switched off by a weight of 0; with every weight 0, R = M exactly. Why these
// weights: participation and footprint are near-constraints (a parked or overlapping controller
// costs more than any M). Redundancy and centring are tie-breakers: one frame in a hundred with an
// unseen finger adds 0.01 to M, as much as redundancy changes when S2 moves by 20 percentage points.
// The axis cut trades against M: on a Monte Carlo pose set no layout with a useful M keeps every
// seen marker within 250 mm, so its weight sets how much M a lab gives for fewer cut coordinates.
// M_cut asks a different question: not how often a controller sees beyond its cut, but how well
// the hand is covered by what lies inside the cuts, which is what the controllers can measure. It
// weighs as much as M (weight 1), so the search keeps every controller counting inside its cut;
// what that costs in M is in docs/results/placement.md.
#include <array>
#include <span>

#include <Eigen/Core>

#include <string>
#include <vector>

#include "core/layout/layout.h"
#include "core/metric/layout_tally.h"

namespace lmc {

enum class PlacementMetricKind : int { kStudy = 0, kRobust = 1 };
const char* placement_metric_name(PlacementMetricKind kind);  // "study", "robust"
// Parses "study" / "robust"; throws lmc::Error naming `what` otherwise.
PlacementMetricKind placement_metric_from_name(const std::string& name, const std::string& what);

struct RobustWeights {
  double redundancy = 0.05;
  double participation = 1.0;  // a parked controller costs 0.25 (with four): more than any M
  double axis_cut = 0.2;
  double centring = 0.01;
  double footprint = 1.0;            // overlapping controllers cannot be built: nearly a constraint
  double participation_floor = 0.2;  // a controller should see some finger in at least this share of frames
  double inside_cut = 1.0;           // M_cut: as much as M (last: positional initialisers stay valid)
  bool operator==(const RobustWeights&) const = default;
  // Every term off (R = M exactly); the participation floor as by default.
  static RobustWeights all_off() { return {0, 0, 0, 0, 0, 0.2, 0}; }
};

// The raw value of each term and the total.
struct RobustTerms {
  double metric_m = 0;             // the study's M
  double redundancy = 0;           // 1 − S2
  double participation = 0;        // P
  double axis_cut = 0;             // A
  double centring = 0;             // C
  double footprint = 0;            // F
  double metric_m_inside_cut = 0;  // M_cut
  double total = 0;                // R
};

// Every term in the order R adds them, for every report of them (text, JSON, the layout report).
struct RobustTermInfo {
  const char* key;                // JSON key and --w-<key with dashes> option
  const char* name;               // short, for tables
  const char* meaning;            // one line
  double RobustWeights::*weight;  // null for M, whose weight is 1
  double RobustTerms::*value;
};
std::span<const RobustTermInfo> robust_term_infos();
double robust_term_weight(const RobustWeights& weights, const RobustTermInfo& term);

// Footprint corners on the table (world x, z) of one device: its model's case
// (LayoutDevice::footprint_mm), 80 × 30 mm for the original controller.
inline constexpr double kControllerLengthMm = 80.0;
inline constexpr double kControllerWidthMm = 30.0;
bool footprints_overlap(const LayoutDevice& a, const LayoutDevice& b);
// A controller's case on the table as the (x, z) corners the overlap test uses; the
// layout report's top view draws the same corners.
std::array<Eigen::Vector2d, 4> controller_footprint(const LayoutDevice& d);
double footprint_overlap_share(const Layout& layout);

RobustTerms robust_terms(const LayoutTally& tally, double footprint_share, const RobustWeights& weights);

}  // namespace lmc
