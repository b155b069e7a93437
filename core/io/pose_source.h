#pragma once
// One way for every tool to say which poses to use: "mc" (the default Monte Carlo set, generated
// from a hand model with a seed) or the path of a pose-set file (core/io/pose_set_tsv.h).
#include <cstdint>
#include <optional>
#include <string>

#include "core/hand/hand_model.h"
#include "core/hand/pose_set.h"

namespace lmc {

inline constexpr int kDefaultMonteCarloFrames = 10000;
inline constexpr std::uint64_t kDefaultMonteCarloSeed = 1;

// The hand to generate poses with: the published-anthropometry default, or the first row with a
// hand in an LMC recording (any variant core/io/lmc_recording.h reads), e.g.
// reference-data/optimization/Static.txt. Throws lmc::Error naming the file.
HandModel load_hand_model(const std::optional<std::string>& recording_path);

// "mc" → generate_pose_set(hand, {frames, seed}); anything else is read as a pose-set file
// (frames/seed are then ignored). Throws lmc::Error.
PoseSet load_poses(const std::string& spec, int frames = kDefaultMonteCarloFrames,
                   std::uint64_t seed = kDefaultMonteCarloSeed,
                   const std::optional<std::string>& hand_path = std::nullopt);

}  // namespace lmc
