#pragma once
// A pose-set recipe: several recordings (and pose-set files) mixed with weights, plus a share of
// the Monte Carlo set, so a layout can be designed for "index and thumb trials 2:1, plus 20 % Monte
// Carlo". One small JSON file that `lmc optimize --poses`, `lmc evaluate --poses` and the Layout tab
// read (docs/formats.md):
//   {"format": "lmc-pose-recipe", "format_version": 1,
//    "frames": 12000,                       // optional: the set's size (default: every recorded
//                                           //   frame once, plus the Monte Carlo share on top)
//    "parts": [                             // at least one, unless the Monte Carlo share is all
//      {"from": ["results/S01"], "source": "fused", "trials": "*Index*", "every": 1, "weight": 2},
//      {"poses": "other.tsv", "weight": 1}  // a pose-set file instead of recordings
//    ],
//    "monte_carlo": {"share": 0.2, "seed": 1, "hand": "Static.txt"}}  // optional
// Relative paths are relative to the recipe's folder. `source` is fused (default), vicon or LMCn
// (recorded_poses.h); `trials` a shell pattern on trial names; `every` keeps every N-th frame.
//
// Mixing: the recorded frames get 1 − share of the set, split between the parts in proportion to
// their weights; part i's N_i frames are taken evenly across its own frames (frame ⌊(k + ½)·n_i/N_i⌋,
// k = 0 … N_i − 1: thinned when it has more than its share, repeated when it has fewer), so the set
// is the same on every machine and the search's determinism for a seed is untouched. The Monte
// Carlo frames are the default generator's (core/hand/pose_set_generator.h) with the recipe's seed.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/hand/pose_set.h"
#include "core/poses/recorded_poses.h"

namespace lmc {

struct PoseRecipePart {
  std::vector<std::filesystem::path> from;  // recordings (resolved)
  RecordedPoseOptions options;
  std::optional<std::filesystem::path> poses;  // or a pose-set file (resolved)
  double weight = 1.0;
};

struct PoseRecipe {
  std::string source;  // the recipe file, for messages and the set's description
  std::optional<int> frames;
  std::vector<PoseRecipePart> parts;
  double monte_carlo_share = 0.0;
  std::uint64_t monte_carlo_seed = 1;
  std::optional<std::string> monte_carlo_hand;  // an LMC recording whose first hand shapes the set
};

// Throws lmc::Error naming the file and the JSON path of the problem.
PoseRecipe parse_pose_recipe(const std::string& text, const std::string& source, const std::filesystem::path& base_dir);
PoseRecipe load_pose_recipe(const std::filesystem::path& path);

// Builds the mixed set. Messages about trials left out go to `notes` (optional).
PoseSet build_pose_set(const PoseRecipe& recipe, std::vector<std::string>* notes = nullptr);

// Every --poses option: "mc" (the Monte Carlo set with these frames/seed/hand), a recipe (a `.json`
// file) or a pose-set file (core/io/pose_set_tsv.h). Throws lmc::Error.
PoseSet load_pose_spec(const std::string& spec, int frames, std::uint64_t seed,
                       const std::optional<std::string>& hand_path, std::vector<std::string>* notes = nullptr);

}  // namespace lmc
