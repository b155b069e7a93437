#pragma once
// Stage 5 (docs/algorithms/processing.md): segment and finger lengths, the six joint angles,
// per-trial statistics and the per-device visibility table — identical for fused LMC points and
// for Vicon points mapped to the 30-point layout.
#include <array>
#include <span>
#include <string_view>
#include <vector>

#include "core/hand/hand_track.h"
#include "core/io/lmc_recording.h"

namespace lmc {

inline constexpr int kNumSegments = 14;
inline constexpr int kNumFingers = 5;
inline constexpr int kNumAngles = 6;

// Column names as in the authors' result file.
std::string_view segment_name(int s);  // "Thumb_interm" … "Little_distal"
std::string_view finger_name(int f);   // "Thumb", "Finger", "Middle", "Ring", "Little" (their header)
// "index_mcp", "index_pip", "index_dip", "thumb_mcp", "thumb_dip", "wrist" — the column order of
// the angle table (their header row reuses the finger names; the six columns are in this order).
std::string_view angle_name(int a);

// Point pairs (from, to) of each segment; finger f's segments.
std::array<int, 2> segment_points(int s);
std::span<const int> finger_segments(int f);  // a view of a constant table (measures.cpp)

struct FrameMeasures {
  std::array<double, kNumSegments> segment_mm{};
  std::array<double, kNumFingers> finger_mm{};
  std::array<double, kNumAngles> angle_deg{};
};

// Angle between the vectors a→b and c→d in degrees: 0 when either has zero length (as the study),
// NaN when a point is NaN. The cosine is clamped to [−1, 1] (it leaves that range only by rounding;
// the study's numpy gave NaN there and silently skipped such frames).
double joint_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

FrameMeasures measure_frame(const HandTrack& track, int frame);
std::vector<FrameMeasures> measure_track(const HandTrack& track);

// Per-trial statistics (NaN skipped; NaN when every frame is NaN).
struct MeasureStats {
  std::array<double, kNumSegments> segment_min{}, segment_max{}, segment_mean{};
  std::array<double, kNumFingers> finger_min{}, finger_max{}, finger_mean{};
  std::array<double, kNumAngles> angle_min{}, angle_max{}, angle_rom{};  // rom = max − min
};
MeasureStats summarize(const std::vector<FrameMeasures>& frames);

// Visibility table of one device (the authors' 4 rows × 5 fingers): counts of −1 (no hand),
// 0 (hidden: internal-model guess), 1 (visible), and the rate n1 / (n0 + n1), or −1 when the device
// never reported the hand.
struct VisibilityCounts {
  int device_id = 0;
  std::array<int, kNumDigits> n_no_hand{}, n_hidden{}, n_visible{};
  std::array<double, kNumDigits> rate{};
};
VisibilityCounts visibility_table(int device_id, const std::vector<FingerLabels>& labels);

}  // namespace lmc
