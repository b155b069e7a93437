#pragma once
// Several particle swarms from different seeds: the best layout, and the runners-up
// that are really different layouts rather than the same one found twice.
//
// Start k uses seed `settings.seed + k`; the starts run one after another, each using every
// thread inside (run_pso), so the result depends on the seed and the number of starts only,
// never on the thread count. Only start 0 honours `start_from_layout`, so the others explore.
#include <functional>
#include <span>
#include <stop_token>
#include <vector>

#include "core/optimise/pso.h"

namespace lmc {

struct MultiStartProgress {
  int start = 0;    // the start running (0-based)
  int starts = 0;   // planned
  PsoProgress pso;  // that start's progress
};
using MultiStartProgressCallback = std::function<void(const MultiStartProgress&)>;

struct MultiStartResult {
  JobStatus status = JobStatus::kCompleted;
  std::vector<PsoResult> runs;  // one per finished start, in start order
  std::vector<std::uint64_t> seeds;
  int best = -1;                // index into runs (lowest cost; ties: the earlier start)
  std::vector<int> runners_up;  // indices into runs, by cost, each distinct from the best and from each other
  double seconds = 0;
};

// Two layouts are the same arrangement when some pairing of their devices puts every pair
// within `mm` in x and z and `deg` in rx and ry (slot names do not matter: swapping two
// controllers gives the same set-up).
bool same_arrangement(const Layout& a, const Layout& b, double mm = 50.0, double deg = 15.0);

// Throws lmc::Error for starts outside 1…64 and whatever run_pso throws.
MultiStartResult run_multi_start(const Layout& start, const SearchSpace& space, std::span<const PreparedFrame> frames,
                                 const PsoSettings& settings, int starts,
                                 const MultiStartProgressCallback& progress = {}, std::stop_token stop = {});

}  // namespace lmc
