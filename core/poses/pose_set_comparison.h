#pragma once
// How far is one pose set from another (the invented Monte Carlo set from a lab's recorded hands)?
// Per quantity — where the hand is (palm position x, y, z), how it is turned (palm tilt, heading
// and pitch of the hand, from estimate_palm_axes so both sets use one definition whatever produced
// them) and how it is bent (the study's six joint angles, core/processing/measures.h) — both sets'
// distributions on a common histogram, their overlap (Σ min of the two shares: 1 = the same
// distribution, 0 = disjoint), the medians, and the ranges one set visits and the other never does.
// Then, over whole hands: the share of each set's frames whose cell (palm position in 30 mm cubes ×
// palm tilt in 30° steps) the other set never visits.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/hand/pose_set.h"

namespace lmc {

struct QuantityComparison {
  std::string name;                      // "palm height (y)"
  std::string unit;                      // "mm", "°"
  double lo = 0, hi = 0;                 // the common histogram's range
  std::vector<double> a_share, b_share;  // per bin, each summing to 1 over the set's finite values
  double overlap = 0;                    // Σ min(a_share, b_share)
  double a_median = 0, b_median = 0;
  // Ranges (lo, hi) holding ≥ 1 % of one set's values where the other has none.
  std::vector<std::pair<double, double>> a_only, b_only;
};

struct PoseSetComparison {
  std::string a_name, b_name;  // descriptions
  int a_frames = 0, b_frames = 0;
  std::vector<QuantityComparison> quantities;
  double a_hands_b_never_has = 0;  // share of A's frames in (position, tilt) cells B never visits
  double b_hands_a_never_has = 0;
};

PoseSetComparison compare_pose_sets(const PoseSet& a, const PoseSet& b, int bins = 40);

std::string format_pose_set_comparison(const PoseSetComparison& c);
nlohmann::json pose_set_comparison_json(const PoseSetComparison& c);
// Small multiples: one panel per quantity, both histograms as steps, the overlap in the title.
std::string pose_set_comparison_svg(const PoseSetComparison& c, const std::string& a_label, const std::string& b_label);

}  // namespace lmc
