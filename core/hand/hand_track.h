#pragma once
// A *hand track* is a hand on the processing grid: `frame_count` frames of the study's 30 entries
// (28 points + palm normal + palm direction, docs/algorithms/hand-points.md), stored frame-major in one
// flat array so every stage (resample, realign, fuse, measure) walks memory in order. A frame
// without data holds NaN in all 30 entries; a single NaN entry is allowed too (e.g. a Vicon marker
// missing for one frame).
#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "core/common/nan.h"
#include "core/hand/hand_frame.h"

namespace lmc {

inline bool is_finite(const Vec3& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

struct HandTrack {
  int frame_count = 0;
  std::vector<Vec3> points;  // points[f * kNumHandPoints + i]

  HandTrack() = default;
  explicit HandTrack(int frames)
      : frame_count(frames), points(static_cast<size_t>(frames) * kNumHandPoints, Vec3::Constant(kNaN)) {}

  Vec3& at(int frame, int point) {
    return points[static_cast<size_t>(frame) * kNumHandPoints + static_cast<size_t>(point)];
  }
  const Vec3& at(int frame, int point) const {
    return points[static_cast<size_t>(frame) * kNumHandPoints + static_cast<size_t>(point)];
  }
  // True when the frame has a hand (the palm position is finite: producers write whole frames).
  bool has_hand(int frame) const { return is_finite(at(frame, kPalm)); }
  void resize(int frames) {
    frame_count = frames;
    points.resize(static_cast<size_t>(frames) * kNumHandPoints, Vec3::Constant(kNaN));
  }
};

// One device's stream on the grid.
struct DeviceTrack {
  int device_id = 0;  // 1-based as in the recording (LMC1 = 1)
  HandTrack track;
};

// Every device of one trial on a common time grid: frame f is at start_us + f·step_us on the
// shared LeapGetNow() clock (devices/leapc/README.md).
struct GridTrial {
  std::int64_t start_us = 0;
  double step_us = 10000.0;  // 100 Hz (docs/algorithms/processing.md)
  int frame_count = 0;
  std::vector<DeviceTrack> devices;  // ascending device_id

  double time_s(int frame) const { return frame * step_us * 1e-6; }
};

}  // namespace lmc
