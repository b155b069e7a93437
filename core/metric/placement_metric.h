#pragma once
// The placement metric M of docs/algorithms/metric.md (what the authors' code computes; the
// paper's printed formula is garbled): M = Σ_{i=0}^{D−1} c_i / N^(i+1). Lower is better; 0 when
// every device sees every finger in every frame. A single frame with an unseen finger outweighs
// any number of frames seen by one device only.
#include <cstdint>
#include <span>

namespace lmc {

// c has D + 1 entries (c_0 … c_D); N = Σ c_i (0 frames → 0).
double placement_metric(std::span<const std::int64_t> c);

}  // namespace lmc
