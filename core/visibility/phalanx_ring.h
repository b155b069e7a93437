#pragma once
// The batch kernel's form of the finger-occlusion test, visibility step 4 (visibility_tests.h has the
// reference form, which the explaining path uses). Same expressions, evaluated in the same order
// per (ray, phalanx), so every decision is bit-for-bit the reference's; only the work around them
// differs. Why it is faster (this test is most of a robust search's instructions; the measurements
// are in docs/results/placement.md):
//
//  * Only the 12 phalanges of the other four fingers are tested. The reference block has 16 lanes
//    (15 phalanges + a dummy) and masks the ray's own finger away afterwards, so a quarter of the
//    arithmetic was thrown away. Here the 15 phalanges sit in a ring of 24 lanes (lanes 15…23
//    repeat lanes 0…8) so that finger f's 12 others are the contiguous lanes
//    others_start(f) … others_start(f) + 11: three AVX2 vectors, no mask, no remainder.
//  * The test runs in two stages. Stage 1 is the line-distance condition (n·e)² < r²·n·n with
//    n·n > 0; only when some lane passes it does stage 2 compute the segment conditions on t1 and
//    t2. Stage 1 alone clears most rays (a ray to a seen fingertip usually passes more than a
//    radius from every other finger's line); stage 2 reuses n·n from stage 1.
//
// No cheaper bounding volume in front: a sphere around each other finger or around each phalanx
// clears fewer rays than stage 1, and the phalanx spheres cost about as much as stage 1, which is
// exact.
#include <cstdint>

#include "core/common/always_inline.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_tests.h"

namespace lmc::vis {

inline constexpr int kRingLanes = 24;
inline constexpr int kOtherPhalanges = 12;

// First ring lane of the 12 phalanges that may hide finger f (the fingers after f, then those
// before it, wrapping around).
constexpr int others_start(int finger) {
  return finger == kNumDigits - 1 ? 0 : 3 * (finger + 1);
}

// Per (device, frame), as PhalanxBlock: e = b − o, w, g = w × e, w·e, w·w, length.
struct PhalanxRing {
  alignas(64) double ex[kRingLanes], ey[kRingLanes], ez[kRingLanes];
  alignas(64) double wx[kRingLanes], wy[kRingLanes], wz[kRingLanes];
  alignas(64) double gx[kRingLanes], gy[kRingLanes], gz[kRingLanes];
  alignas(64) double we[kRingLanes], ww[kRingLanes], len[kRingLanes];
};

// The phalanges as prepare_phalanges computes them (set_phalanx_lane), then the wrap-around copies.
LMC_ALWAYS_INLINE void prepare_phalanx_ring(const PreparedFrame& fr, const DeviceView& d, PhalanxRing& r) {
  for (int p = 0; p < kNumPhalanges; ++p) set_phalanx_lane(fr, d, p, r);
  for (int p = kNumPhalanges; p < kRingLanes; ++p) {
    const int q = p - kNumPhalanges;
    r.ex[p] = r.ex[q];
    r.ey[p] = r.ey[q];
    r.ez[p] = r.ez[q];
    r.wx[p] = r.wx[q];
    r.wy[p] = r.wy[q];
    r.wz[p] = r.wz[q];
    r.gx[p] = r.gx[q];
    r.gy[p] = r.gy[q];
    r.gz[p] = r.gz[q];
    r.we[p] = r.we[q];
    r.ww[p] = r.ww[q];
    r.len[p] = r.len[q];
  }
}

// True when some phalanx of the 12 lanes from `start` hides the ray o → m (v = m − o, vv = v·v):
// exactly phalanx_occludes(…) for any of them (see visibility_tests.h for the derivation). Plain
// loops over all 12 lanes with branch-free bodies and integer masks, so that GCC vectorises both
// stages. (Running stage 2 only on the groups of four lanes that kept a lane, with GCC vector
// extensions or with 4-lane loops, compiles to more instructions.)
LMC_ALWAYS_INLINE bool others_occlude(const PhalanxRing& r, int start, double vx, double vy, double vz, double vv,
                                      double radius_sq) {
  const double* const wx = r.wx + start;
  const double* const wy = r.wy + start;
  const double* const wz = r.wz + start;
  const double* const gx = r.gx + start;
  const double* const gy = r.gy + start;
  const double* const gz = r.gz + start;
  // Stage 1: how far the ray's line passes from each phalanx line.
  double nn[kOtherPhalanges];
  std::int64_t near[kOtherPhalanges];
  std::int64_t any_near = 0;
  for (int p = 0; p < kOtherPhalanges; ++p) {
    const double nx = vy * wz[p] - vz * wy[p];
    const double ny = vz * wx[p] - vx * wz[p];
    const double nz = vx * wy[p] - vy * wx[p];
    const double n2 = nx * nx + ny * ny + nz * nz;
    const double ne = vx * gx[p] + vy * gy[p] + vz * gz[p];
    nn[p] = n2;
    near[p] = ((n2 > 0.0) & (ne * ne < radius_sq * n2)) ? -1 : 0;
    any_near |= near[p];
  }
  if (any_near == 0) return false;
  // Stage 2: is the closest approach inside the ray segment and inside the phalanx?
  const double* const ex = r.ex + start;
  const double* const ey = r.ey + start;
  const double* const ez = r.ez + start;
  const double* const we = r.we + start;
  const double* const ww = r.ww + start;
  const double* const len = r.len + start;
  std::int64_t any = 0;
  for (int p = 0; p < kOtherPhalanges; ++p) {
    const double ve = vx * ex[p] + vy * ey[p] + vz * ez[p];
    const double vw = vx * wx[p] + vy * wy[p] + vz * wz[p];
    const double t1 = ve * ww[p] - vw * we[p];
    const double t2 = vw * ve - vv * we[p];
    const std::int64_t hit = ((t1 > 0.0) & (t1 <= nn[p]) & (t2 > 0.0) & (t2 < len[p] * nn[p])) ? -1 : 0;
    any |= hit & near[p];
  }
  return any != 0;
}

}  // namespace lmc::vis
