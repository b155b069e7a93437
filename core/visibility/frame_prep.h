#pragma once
// Per-frame data that every device shares (docs/algorithms/hand-points.md, docs/algorithms/visibility.md), computed
// once per frame so that each (device, frame) test is only the device-dependent arithmetic:
//  * the 22 ray-tracing markers s0…s21 (s0 elbow, s1–s4 thumb Proxi…End, s5–s8 index,
//    s9–s12 middle, s13–s16 ring, s17 pinky Meta, s18–s21 pinky Proxi…End);
//  * the approach vector a = (s1 + s17)/2 − s0;
//  * the palm plane (centroid, unit normal: palm_plane_normal) and the
//    facet planes of the six palm points' 3-D convex hull;
//  * the 15 phalanges (3 per finger): base, unit direction, length.
// Laid out as structure-of-arrays so the inner loops vectorise.
#include <array>
#include <span>
#include <vector>

#include "core/geometry/palm_hull.h"
#include "core/hand/hand_frame.h"

namespace lmc {

inline constexpr int kNumRayMarkers = 22;
inline constexpr int kNumFingerMarkers = 20;  // four per finger (s17, pinky Meta, belongs to none)
inline constexpr int kNumPhalanges = 15;
inline constexpr int kNumPalmPoints = 6;

// Hand point (hand_frame.h index) of ray marker s_k.
int ray_marker_hand_point(int k);
// The ray marker index of finger f's j-th marker (j = 0…3): thumb s1–s4, …, pinky s18–s21.
constexpr int finger_marker(int finger, int j) {
  return finger < 4 ? 1 + 4 * finger + j : 18 + j;
}

struct PreparedFrame {
  // Markers s0…s21 in world coordinates (SoA).
  std::array<double, kNumRayMarkers> mx{}, my{}, mz{};
  // Approach (forearm) vector.
  double ax = 0, ay = 0, az = 0;
  // Palm plane through (cx, cy, cz) with unit normal (nx, ny, nz).
  double cx = 0, cy = 0, cz = 0, nx = 0, ny = 0, nz = 0;
  std::array<Eigen::Vector3d, kNumPalmPoints> palm_points{};
  ConvexHull6 hull;
  // Phalanx p (= 3·finger + segment): base b, unit direction w, length len (SoA). A zero-length
  // phalanx has w = 0 and never occludes (its n = v × w is zero: "parallel").
  std::array<double, kNumPhalanges> bx{}, by{}, bz{}, wx{}, wy{}, wz{}, len{};
  // False when the frame has no hand or non-finite coordinates: nothing is visible.
  bool valid = false;
};

// The palm plane's unit normal from the palm points minus their centroid: the study's "right
// singular vector of the smallest singular value", computed as the eigenvector of the smallest
// eigenvalue of the 3 × 3 scatter matrix (least_variance_direction). That is the same line (to
// 1e-13 or better for a hand's palm; PalmNormal.* compares it with an SVD) in much less time than
// Eigen's 6 × 3 JacobiSVD, on a path run once per frame of every device. Its sign is arbitrary, as an
// SVD's is: the palm test divides one dot product with it by another, so the sign cancels exactly.
Eigen::Vector3d palm_plane_normal(const Eigen::Matrix<double, kNumPalmPoints, 3>& centred);

PreparedFrame prepare_frame(const HandFrame& frame);
// The same into `out`, which may hold an earlier frame: a frame without a hand or with a
// non-finite marker sets valid = false, and the rest is then unspecified (nothing reads it). For
// loops over a trial's frames, which would otherwise zero and copy a 2 KB frame each time.
void prepare_frame_into(std::span<const Vec3, kNumHandPoints> points, bool hand_present, PreparedFrame& out);
// Prepares many frames (in parallel; the result does not depend on the thread count).
std::vector<PreparedFrame> prepare_frames(std::span<const HandFrame> frames);

}  // namespace lmc
