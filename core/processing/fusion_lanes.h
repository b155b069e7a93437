#pragma once
// What the default fusion (fusion_smoother.h, online_fusion.h) combines and filters: the 30 points
// coordinate by coordinate, as before, and beside them the length of every finger bone from the
// MCP joint outward as a quantity of its own.
//
// Why: averaging the *points* of controllers whose realigned hands disagree in position
// and rotation shortens every bone (two 30 mm bones turned 40° apart average to 28.2 mm), and
// weights that differ between the joints of one finger stitch the fused finger from hands that are
// ~10 mm apart. On the study's real trial that made the fused middle finger 10 mm shorter than the
// median controller. A bone length combined as a number stays between the controllers' lengths
// whatever the weights and however misaligned their frames.
//
// The fused hand takes the fused points for position and for each bone's direction, and the fused
// lengths for the bones: each digit is rebuilt outward from its fused MCP joint (Proxi), bone by
// bone. Directions stay differences of fused points (separately averaged directions would add
// every bone's noise to the fingertip). The metacarpal (Meta → Proxi) is left as fused: it is in
// no finger length, and the thumb's is zero long in the controller's model, where noise alone
// would give it a length.
//
// Lanes (each filtered as one coordinate by the constant-velocity Kalman filter, cv_kalman.h):
// 3·i + c for point i, coordinate c; then kFirstLengthLane + 3·digit + k for the bones
// Proxi→Inter, Inter→Dist, Dist→End (k = 0, 1, 2) of each digit.
#include <span>

#include "core/hand/hand_frame.h"

namespace lmc {

inline constexpr int kRebuiltFromJoint = 1;  // Proxi (MCP)
inline constexpr int kRebuiltBonesPerDigit = kJointsPerDigit - 1 - kRebuiltFromJoint;
inline constexpr int kFirstLengthLane = 3 * kNumHandPoints;
inline constexpr int kFusionLanes = kFirstLengthLane + kNumDigits * kRebuiltBonesPerDigit;

// One device sample (world frame) → lane values and their measurement variances. `factors` are the
// per-point variance factors (frame_quality); `base_var` the variance of a visible point (mm²). A
// bone's length gets 2 × base_var × the larger factor of its two joints (a difference of two
// points). Non-finite points give NaN lanes.
void hand_to_lanes(std::span<const Vec3, kNumHandPoints> points, std::span<const float, kNumHandPoints> factors,
                   double base_var, std::span<double, kFusionLanes> value, std::span<double, kFusionLanes> variance);

// Fused lanes → points: the palm, vectors, elbow, wrist and each digit's Meta and Proxi joints as
// fused; the further joints rebuilt bone by bone along the direction between the bone's fused
// joints with its fused length (clamped at 0). A bone whose fused joints coincide stays zero. NaN in
// a lane a point depends on makes it NaN.
void lanes_to_hand(std::span<const double, kFusionLanes> value, std::span<Vec3, kNumHandPoints> points);

}  // namespace lmc
