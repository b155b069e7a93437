#include "core/io/pose_source.h"

#include "core/common/error.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/lmc_recording.h"
#include "core/io/pose_set_tsv.h"

namespace lmc {

HandModel load_hand_model(const std::optional<std::string>& recording_path) {
  if (!recording_path) return HandModel();
  const LmcRecording rec = read_lmc_recording(*recording_path);
  for (const auto& row : rec.rows) {
    if (row.hand_present) return HandModel(row);
  }
  throw Error(ErrorLocation(*recording_path), "no row with a hand in this recording");
}

PoseSet load_poses(const std::string& spec, int frames, std::uint64_t seed,
                   const std::optional<std::string>& hand_path) {
  if (spec == "mc") {
    PoseSetSettings settings;
    settings.frames = frames;
    settings.seed = seed;
    PoseSet set = generate_pose_set(load_hand_model(hand_path), settings);
    if (hand_path) set.description += " hand=" + *hand_path;
    return set;
  }
  return load_pose_set(spec);
}

}  // namespace lmc
