#pragma once
// The elementary tests of docs/algorithms/visibility.md (its steps 1–4), each written once and used by both the
// batch kernel (visibility_kernel.cpp) and the explaining path (visibility_explain.cpp), so the
// two can never disagree. Everything is double precision, like the authors' numpy code.
#include <cmath>

#include "core/common/always_inline.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_params.h"

namespace lmc::vis {

// Visibility step 1: the hand must enter from the user's side, a·f ≥ 0.
inline double approach_dot(const PreparedFrame& fr, const DeviceView& d) {
  return fr.ax * d.fx + fr.ay * d.fy + fr.az * d.fz;
}
inline bool approach_ok(const PreparedFrame& fr, const DeviceView& d) {
  return approach_dot(fr, d) >= 0.0;
}

enum class ViewResult : int { kInside = 0, kOutOfRange = 1, kOutOfView = 2 };

// Visibility step 2 for one marker m: distance to the device origin, then the pyramid in the device frame
// (|p.x| ≤ p.y·tan(long/2), |p.z| ≤ p.y·tan(short/2); on a plane counts as inside).
inline ViewResult marker_in_view(double mx, double my, double mz, const DeviceView& d, const VisibilityLimits& lim) {
  const double vx = mx - d.ox, vy = my - d.oy, vz = mz - d.oz;
  // The authors compare the Euclidean norm with L; comparing |v| itself (not |v|²) keeps ties
  // identical to theirs.
  const double v2 = vx * vx + vy * vy + vz * vz;
  if (std::sqrt(v2) > lim.range_mm) return ViewResult::kOutOfRange;
  // Too near to track (the controller's near limit; 0 in the study's model, never true then).
  if (v2 < lim.range_near_sq) return ViewResult::kOutOfRange;
  const double px = d.rt[0] * vx + d.rt[1] * vy + d.rt[2] * vz;
  const double py = d.rt[3] * vx + d.rt[4] * vy + d.rt[5] * vz;
  const double pz = d.rt[6] * vx + d.rt[7] * vy + d.rt[8] * vz;
  if (std::abs(px) > py * lim.tan_half_long || std::abs(pz) > py * lim.tan_half_short) return ViewResult::kOutOfView;
  return ViewResult::kInside;
}

// Shared by all rays of one (device, frame): n·(c − o) for the palm plane.
inline double palm_plane_numerator(const PreparedFrame& fr, const DeviceView& d) {
  return fr.nx * (fr.cx - d.ox) + fr.ny * (fr.cy - d.oy) + fr.nz * (fr.cz - d.oz);
}

// Visibility step 3 for the ray o → m, v = m − o (not normalised): the line meets the palm plane at
// q = o + t·v with t = n·(c − o) / n·v; occluded when 0 < t < 1 (strictly between device and
// marker) and q lies in the palm points' 3-D hull. A ray parallel to the plane (n·v = 0) is not
// occluded.
inline bool palm_occludes(const PreparedFrame& fr, const DeviceView& d, double plane_num, double vx, double vy,
                          double vz) {
  const double denom = fr.nx * vx + fr.ny * vy + fr.nz * vz;
  if (denom == 0.0) return false;
  const double t = plane_num / denom;
  if (!(t > 0.0 && t < 1.0)) return false;
  return hull_contains(fr.hull, d.ox + t * vx, d.oy + t * vy, d.oz + t * vz);
}

// Visibility step 4, the device-dependent part of each phalanx, computed once per (device, frame) and shared
// by all rays: e = b − o, g = w × e, w·e, w·w, plus w and the length. 16 lanes (the 16th is a
// zero-length dummy that never occludes) so the per-ray loop vectorises without a remainder.
inline constexpr int kPhalanxLanes = 16;
struct PhalanxBlock {
  alignas(64) double ex[kPhalanxLanes], ey[kPhalanxLanes], ez[kPhalanxLanes];
  alignas(64) double wx[kPhalanxLanes], wy[kPhalanxLanes], wz[kPhalanxLanes];
  alignas(64) double gx[kPhalanxLanes], gy[kPhalanxLanes], gz[kPhalanxLanes];
  alignas(64) double we[kPhalanxLanes], ww[kPhalanxLanes], len[kPhalanxLanes];
};

// Phalanx p of the frame, as seen from the device, into lane p of a block of lanes (PhalanxBlock
// here, the batch kernel's PhalanxRing): the one place these per-phalanx numbers are computed.
template <class Lanes>
LMC_ALWAYS_INLINE void set_phalanx_lane(const PreparedFrame& fr, const DeviceView& d, int p, Lanes& lanes) {
  const auto pp = static_cast<size_t>(p);
  const double ex = fr.bx[pp] - d.ox, ey = fr.by[pp] - d.oy, ez = fr.bz[pp] - d.oz;
  const double wx = fr.wx[pp], wy = fr.wy[pp], wz = fr.wz[pp];
  lanes.ex[p] = ex;
  lanes.ey[p] = ey;
  lanes.ez[p] = ez;
  lanes.wx[p] = wx;
  lanes.wy[p] = wy;
  lanes.wz[p] = wz;
  lanes.gx[p] = wy * ez - wz * ey;
  lanes.gy[p] = wz * ex - wx * ez;
  lanes.gz[p] = wx * ey - wy * ex;
  lanes.we[p] = wx * ex + wy * ey + wz * ez;
  lanes.ww[p] = wx * wx + wy * wy + wz * wz;
  lanes.len[p] = fr.len[pp];
}

inline void prepare_phalanges(const PreparedFrame& fr, const DeviceView& d, PhalanxBlock& pb) {
  for (int p = 0; p < kPhalanxLanes; ++p) {
    if (p >= kNumPhalanges) {
      pb.ex[p] = pb.ey[p] = pb.ez[p] = pb.wx[p] = pb.wy[p] = pb.wz[p] = 0.0;
      pb.gx[p] = pb.gy[p] = pb.gz[p] = pb.we[p] = pb.ww[p] = pb.len[p] = 0.0;
      continue;
    }
    set_phalanx_lane(fr, d, p, pb);
  }
}

// Visibility step 4 for the ray o → m (v = m − o, not normalised, vv = v·v) against phalanx p of `pb`.
// With unit v̂ = v/D the study's conditions are d < r, 0 < t1 ≤ D, 0 < t2 < ℓ where n̂ = v̂ × w,
// d = |n̂·e|/|n̂|, t1 = (w × n̂)·e / n̂·n̂, t2 = (v̂ × n̂)·e / n̂·n̂. With n = v × w = D·n̂ they read
//   (n·e)² < r²·n·n,   0 < (w × n)·e ≤ n·n,   0 < (v × n)·e < ℓ·n·n
// (no square root, no division), and by the vector triple product
//   n·e = v·(w × e) = v·g,   (w × n)·e = (v·e)(w·w) − (v·w)(w·e),   (v × n)·e = (v·w)(v·e) − (v·v)(w·e).
// n·n is taken from the cross product itself so that parallel lines give exactly n = 0 and do not
// occlude, as in the study; a zero-length phalanx (w = 0) never occludes either.
inline bool phalanx_occludes(const PhalanxBlock& pb, int p, double vx, double vy, double vz, double vv,
                             double radius_sq) {
  const double wx = pb.wx[p], wy = pb.wy[p], wz = pb.wz[p];
  const double nx = vy * wz - vz * wy;
  const double ny = vz * wx - vx * wz;
  const double nz = vx * wy - vy * wx;
  const double nn = nx * nx + ny * ny + nz * nz;
  const double ne = vx * pb.gx[p] + vy * pb.gy[p] + vz * pb.gz[p];
  const double ve = vx * pb.ex[p] + vy * pb.ey[p] + vz * pb.ez[p];
  const double vw = vx * wx + vy * wy + vz * wz;
  const double t1 = ve * pb.ww[p] - vw * pb.we[p];
  const double t2 = vw * ve - vv * pb.we[p];
  return (nn > 0.0) & (ne * ne < radius_sq * nn) & (t1 > 0.0) & (t1 <= nn) & (t2 > 0.0) & (t2 < pb.len[p] * nn);
}

}  // namespace lmc::vis
