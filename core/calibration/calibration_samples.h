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
//
// Nor a coordinate the controller clamped at its axis cut: a controller may clamp a coordinate at
// ±250 mm from its centre (paper, Discussion; core/metric/layout_tally.h; the simulator does), so a
// point beyond it reads on the cut, as far off along that axis as it lies beyond. Nothing else
// tells the fit that such a point is wrong, and a controller standing ≈ 250 mm from the hand
// (LMC1 of paper-optimized-as-processed) has its wrist, metacarpal bases and palm flattened onto
// the cut on every frame: the hand looks tilted to it, and a rigid fit turned it 20° to match.
// A clamped coordinate sits *on* the cut; one reported beyond it was not clamped and is kept (the
// published real trial's controllers report palms at y = 263 mm and elbows at 388 mm, a smooth
// spread through 250 with no pile-up there). The clamp spares the point's other coordinates, and
// such a controller keeps too few whole points (two knuckles) to be placed from them alone, so a
// sample keeps the device axes it measured truthfully (DeviceSamples::axes) and the fits use those
// coordinates only (rigid_transform.h's masked fit). One rule for every mode and caller:
// lmc calibrate, the Devices tab, a session block's calibration.
#include <array>
#include <cstdint>
#include <vector>

#include "core/calibration/rigid_transform.h"
#include "core/hand/hand_track.h"
#include "core/io/lmc_recording.h"
#include "core/metric/layout_tally.h"

namespace lmc {

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

  // Device axes whose coordinate the fit may use (bit k: axis k; kAllAxes for a whole point).
  std::vector<std::uint8_t> axes;
  // Samples with a coordinate clamped at the axis cut (used through their other coordinates), and
  // of those, how many had every coordinate clamped (left out).
  int beyond_cut = 0, dropped_beyond_cut = 0;

  int size() const { return static_cast<int>(p.size()); }
  int key(int i) const { return frame[static_cast<size_t>(i)] * kNumCalibrationPoints + point[static_cast<size_t>(i)]; }
};

struct SampleRules {
  double axis_cut_mm = kAxisCutMm;
  // A controller clamps an axis when at least `min_on_cut` of its samples sit on the cut (within
  // `on_cut_tolerance_mm`): a run of clamped frames stays exactly there through the resampler's
  // cubic spline. The published trial's controllers have no such pile-up (their coordinates pass
  // smoothly through 250 mm), so nothing of theirs is masked.
  double on_cut_tolerance_mm = 1e-3;
  int min_on_cut = 5;
  // On an axis the controller clamps, a coordinate in [cut − below, cut + above] (absolute value)
  // counts as clamped: where a point hovers at the cut the spline blends clamped frames with free
  // ones and lands a little inside it, or overshoots a little beyond (the simulator's ring and
  // little knuckles seen by LMC1 above: left in, they cost the fit 0.65°).
  double axis_cut_below_mm = 2.0, axis_cut_above_mm = 0.5;
};

// The device axes on which point `p` (device frame) is not on the axis cut: every axis the
// controller does not clamp (`clamping_axes`, bit k: axis k), and those where p is off the band.
std::uint8_t unclamped_axes(const Vec3& p, std::uint8_t clamping_axes, const SampleRules& rules = {});

// `labels` has one entry per frame of `device_frame_track` (visibility_labels.h).
DeviceSamples gather_samples(const HandTrack& device_frame_track, const std::vector<FingerLabels>& labels,
                             const SampleRules& rules = {});

}  // namespace lmc
