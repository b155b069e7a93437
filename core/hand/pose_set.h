#pragma once
// A pose set: the hand frames a layout is judged on (docs/algorithms/metric.md), world
// coordinates, each with the label of the trial it imitates so tools can filter and split by
// orientation (horizontal / vertical) and motion (open / index / thumb / wrist-flexion /
// wrist-extension).
#include <cstdint>
#include <string>
#include <vector>

#include "core/hand/hand_frame.h"
#include "core/hand/reference_poses.h"

namespace lmc {

struct PoseLabel {
  HandOrientation orientation = HandOrientation::kHorizontal;
  HandMotion motion = HandMotion::kOpen;
  double progress = 0.0;  // along the motion, 0 = open hand, 1 = end of range

  bool operator==(const PoseLabel&) const = default;
};

struct PoseSet {
  std::string description;        // e.g. "monte-carlo seed=1 frames=10000"
  std::vector<HandFrame> frames;  // world coordinates, hand_present = true
  std::vector<PoseLabel> labels;  // one per frame
  // Where the frames came from, one line each for people ("source: fused hand …", "trials: …",
  // "frames: 8120 kept, 31 skipped …"); empty for a Monte Carlo set, whose description says it all.
  // A layout report and `lmc evaluate` print these lines as they are.
  std::vector<std::string> provenance;

  int size() const { return static_cast<int>(frames.size()); }
  // Indices of the frames with this orientation (or motion).
  std::vector<int> indices_with(HandOrientation o) const;
  std::vector<int> indices_with(HandMotion m) const;
};

// A pose set that holds one frame (labels: horizontal/open), e.g. a recorded reference frame.
PoseSet single_frame_pose_set(const HandFrame& frame, std::string description);

}  // namespace lmc
