#include "core/visibility/frame_prep.h"

namespace lmc {

int ray_marker_hand_point(int k) {
  if (k == 0) return kElbow;
  if (k == 17) return digit_point(4, 0);
  if (k < 17) return digit_point((k - 1) / 4, 1 + (k - 1) % 4);
  return digit_point(4, 1 + (k - 18));
}

PreparedFrame prepare_frame(const HandFrame&) { return {}; }

std::vector<PreparedFrame> prepare_frames(std::span<const HandFrame> frames) {
  std::vector<PreparedFrame> out;
  out.reserve(frames.size());
  for (const auto& f : frames) out.push_back(prepare_frame(f));
  return out;
}

}  // namespace lmc
