#pragma once
// Lower bounds on a layout's final cost from part of its pose set, for the search's pruning
// (pso.cpp): a particle whose bound already reaches its own best cost cannot improve on it, so
// the rest of its frames need not be ray-traced, and the search takes exactly the same steps.
//
// Each bound is the cost of a "best-case completion": the counts so far, plus every frame not yet
// counted as the best frame possible (every device sees every finger, no seen marker beyond the
// axis cut, the palm on every viewing axis). Every term of M and R is monotone in those counts
// in the right direction, and so is its floating-point evaluation (IEEE rounding is monotone, the
// counts are exact integers, the expressions are the same ones in the same order), so the bound
// is never above the cost the full pose set gives: not approximately, bit for bit.
#include <cstdint>
#include <span>
#include <vector>

#include "core/metric/layout_tally.h"
#include "core/metric/robust_metric.h"

namespace lmc {

// The study's histogram c_0…c_D with `remaining` more frames in c_D (which M does not weigh).
std::vector<std::int64_t> best_case_histogram(std::span<const std::int64_t> partial_c, std::int64_t remaining);
// The tally with `remaining` more frames in which every device sees every finger, inside the cut
// and on its viewing axis (off-centre 0). device_sole_frames is left as it is.
LayoutTally best_case_tally(const LayoutTally& partial, std::int64_t remaining);

// M and R of the best-case completion: never above the final M or R.
double study_cost_lower_bound(std::span<const std::int64_t> partial_c, std::int64_t remaining);
double robust_cost_lower_bound(const LayoutTally& partial, std::int64_t remaining, double footprint_share,
                               const RobustWeights& weights);

// R is monotone in the counts only when every weight is finite and ≥ 0 (the command line and the
// Optimiser panel allow nothing else); the search does not prune otherwise.
bool robust_bound_holds(const RobustWeights& weights);

}  // namespace lmc
