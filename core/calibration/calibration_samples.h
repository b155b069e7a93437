#pragma once
// Which of a controller's points calibration trusts, and gathering them from a trial.
//
// Only points the controller measures, not guesses: the palm centre, the wrist, and the
// metacarpal bases and knuckles (MCP joints) of the index to little finger. Never the elbow (the
// controller extrapolates it, 10–20 mm off: paper, Discussion) nor the thumb (its metacarpal has
// zero length in the controller's model, so its base is a construction) nor the phalanges (they
// bend during a "still" trial and are the first thing an internal-model guess replaces).
// A digit's points count on a frame only when the ray tracer labelled that finger visible (1);
// the palm and wrist count when any finger is visible — the approach, range and field-of-view
// tests hide all five together, so one visible finger means the hand itself was in view.
#include <array>
#include <vector>

#include "core/io/lmc_recording.h"
#include "core/hand/hand_track.h"

namespace lmc::calibration {

enum PointGroup : int { kGroupPalm = 0, kGroupWrist = 1, kGroupMetacarpalBases = 2, kGroupKnuckles = 3 };
inline constexpr int kNumPointGroups = 4;
// "palm", "wrist", "metacarpal bases", "knuckles"
const char* point_group_name(int group);

struct CalibrationPoint {
  int point = 0;   // HandPoint index (hand_frame.h)
  int group = 0;   // PointGroup
  int digit = -1;  // whose ray-traced label decides; −1: the hand as a whole
};

inline constexpr int kNumCalibrationPoints = 10;
const std::array<CalibrationPoint, kNumCalibrationPoints>& calibration_points();

// One controller's usable samples in device coordinates, ordered by (frame, point).
struct DeviceSamples {
  std::vector<int> frame;  // grid frame
  std::vector<int> point;  // index into calibration_points()
  std::vector<Vec3> p;     // device coordinates (mm)

  int size() const { return static_cast<int>(p.size()); }
  int key(int i) const { return frame[static_cast<size_t>(i)] * kNumCalibrationPoints + point[static_cast<size_t>(i)]; }
};

// `labels` has one entry per frame of `device_frame_track` (visibility_labels.h).
DeviceSamples gather_samples(const HandTrack& device_frame_track, const std::vector<FingerLabels>& labels);

}  // namespace lmc::calibration
