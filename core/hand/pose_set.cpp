#include "core/hand/pose_set.h"

namespace lmc {

std::vector<int> PoseSet::indices_with(HandOrientation o) const {
  std::vector<int> out;
  for (size_t i = 0; i < labels.size(); ++i) {
    if (labels[i].orientation == o) out.push_back(static_cast<int>(i));
  }
  return out;
}

std::vector<int> PoseSet::indices_with(HandMotion m) const {
  std::vector<int> out;
  for (size_t i = 0; i < labels.size(); ++i) {
    if (labels[i].motion == m) out.push_back(static_cast<int>(i));
  }
  return out;
}

PoseSet single_frame_pose_set(const HandFrame& frame, std::string description) {
  PoseSet s;
  s.description = std::move(description);
  s.frames.push_back(frame);
  s.frames.back().hand_present = true;
  s.labels.push_back({});
  return s;
}

}  // namespace lmc
