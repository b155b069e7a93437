#pragma once
// Prepared frames of a seeded Monte Carlo pose set (the default hand), built once per process for
// each (frames, seed) a test asks for: the metric, search and multi-start tests share them.
#include <cstdint>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "core/hand/hand_model.h"
#include "core/hand/pose_set_generator.h"
#include "core/visibility/frame_prep.h"

namespace lmc::test {

inline const std::vector<PreparedFrame>& mc_frames(int frames, std::uint64_t seed) {
  static std::mutex mutex;
  static std::map<std::pair<int, std::uint64_t>, std::vector<PreparedFrame>> cache;
  const std::lock_guard lock(mutex);
  auto it = cache.find({frames, seed});
  if (it == cache.end()) {
    PoseSetSettings s;
    s.frames = frames;
    s.seed = seed;
    it = cache.emplace(std::pair{frames, seed}, prepare_frames(generate_pose_set(HandModel(), s).frames)).first;
  }
  return it->second;
}

}  // namespace lmc::test
