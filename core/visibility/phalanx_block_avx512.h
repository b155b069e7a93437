#pragma once
// The finger-occlusion test (visibility step 4) for CPUs with AVX-512: the ray against all 16 lanes of the ring's
// first block (the 15 phalanges and lane 15, a copy of lane 0) in two 8-lane registers, with the
// ray's own finger and lane 15 masked off, so the lanes tested are exactly others_occlude's 12
// (phalanx_ring.h). Why it is faster than the AVX2 build of others_occlude (measured in
// docs/results/placement.md): CPUs with two 512-bit FMA units run two 512-bit multiplies per cycle
// as they run two 256-bit ones, so 8 lanes per
// instruction halve the instructions of the AVX2 build's 4; every ray of a frame reads the same
// block at the same aligned place, so the block stays in registers (AVX-512 has 32) instead of
// being reloaded at a finger-dependent offset.
//
// Bit for bit the reference's decisions: every lane computes the same IEEE operations in the same
// order as others_occlude. The operations are the _round_ intrinsics with round-to-nearest, which
// GCC never fuses into a multiply-add (AVX-512 has FMA, and a fused a*b+c rounds once instead of
// twice); the kernel's plain code is kept unfused by -ffp-contract=off (cmake/lmc_target_options.cmake),
// which tests/check_no_fused_multiply_add.sh checks in the built program. Ordered compares
// (_CMP_GT_OQ, _CMP_LT_OQ, _CMP_LE_OQ) are false for NaN, as C++'s >, <, <= are.
//
// Not always_inline: GCC refuses to inline an AVX-512 function into the kernel's target-neutral
// body; the AVX-512 entry points are [[gnu::flatten]], which inlines it once the body is inlined
// into them (visibility_kernel.cpp).
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include "core/visibility/phalanx_ring.h"

namespace lmc::vis {

// Lanes 0…14 but finger f's three.
constexpr unsigned others_lane_mask(int finger) {
  return 0x7FFFu & ~(7u << (3 * finger));
}

// Multiply, add, subtract with round-to-nearest, never fused (see above). The zero-masked forms
// with every lane selected are the same instructions; GCC 12's unmasked ones start from an
// "undefined" register its own -Wmaybe-uninitialized flags at -Og.
inline constexpr int kRoundNearest = _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC;
inline constexpr __mmask8 kAllLanes = 0xFF;
[[gnu::target("avx512f"), gnu::always_inline]] inline __m512d mul8(__m512d a, __m512d b) {
  return _mm512_maskz_mul_round_pd(kAllLanes, a, b, kRoundNearest);
}
[[gnu::target("avx512f"), gnu::always_inline]] inline __m512d add8(__m512d a, __m512d b) {
  return _mm512_maskz_add_round_pd(kAllLanes, a, b, kRoundNearest);
}
[[gnu::target("avx512f"), gnu::always_inline]] inline __m512d sub8(__m512d a, __m512d b) {
  return _mm512_maskz_sub_round_pd(kAllLanes, a, b, kRoundNearest);
}

[[gnu::target("avx512f")]] inline bool others_occlude_avx512(const PhalanxRing& r, unsigned lanes, double vx, double vy,
                                                             double vz, double vv, double radius_sq) {
  const __m512d x = _mm512_set1_pd(vx);
  const __m512d y = _mm512_set1_pd(vy);
  const __m512d z = _mm512_set1_pd(vz);
  const __m512d zero = _mm512_setzero_pd();
  // Stage 1 (phalanx_ring.h): how far the ray's line passes from each phalanx line.
  __m512d nn[2];
  __mmask8 near[2];
  for (int q = 0; q < 2; ++q) {
    const int o = 8 * q;
    const __m512d wx = _mm512_load_pd(r.wx + o);
    const __m512d wy = _mm512_load_pd(r.wy + o);
    const __m512d wz = _mm512_load_pd(r.wz + o);
    const __m512d nx = sub8(mul8(y, wz), mul8(z, wy));
    const __m512d ny = sub8(mul8(z, wx), mul8(x, wz));
    const __m512d nz = sub8(mul8(x, wy), mul8(y, wx));
    const __m512d n2 = add8(add8(mul8(nx, nx), mul8(ny, ny)), mul8(nz, nz));
    const __m512d ne = add8(add8(mul8(x, _mm512_load_pd(r.gx + o)), mul8(y, _mm512_load_pd(r.gy + o))),
                            mul8(z, _mm512_load_pd(r.gz + o)));
    nn[q] = n2;
    const auto tested = static_cast<__mmask8>(lanes >> o);
    near[q] = _mm512_mask_cmp_pd_mask(_mm512_mask_cmp_pd_mask(tested, n2, zero, _CMP_GT_OQ), mul8(ne, ne),
                                      mul8(_mm512_set1_pd(radius_sq), n2), _CMP_LT_OQ);
  }
  if ((near[0] | near[1]) == 0) return false;
  // Stage 2: is the closest approach inside the ray segment and inside the phalanx? Both blocks
  // (skipping a block without a near lane gains nothing: the branch is unpredictable).
  const __m512d v2 = _mm512_set1_pd(vv);
  __mmask8 hit_any = 0;
  for (int q = 0; q < 2; ++q) {
    const int o = 8 * q;
    const __m512d ve = add8(add8(mul8(x, _mm512_load_pd(r.ex + o)), mul8(y, _mm512_load_pd(r.ey + o))),
                            mul8(z, _mm512_load_pd(r.ez + o)));
    const __m512d vw = add8(add8(mul8(x, _mm512_load_pd(r.wx + o)), mul8(y, _mm512_load_pd(r.wy + o))),
                            mul8(z, _mm512_load_pd(r.wz + o)));
    const __m512d we = _mm512_load_pd(r.we + o);
    const __m512d t1 = sub8(mul8(ve, _mm512_load_pd(r.ww + o)), mul8(vw, we));
    const __m512d t2 = sub8(mul8(vw, ve), mul8(v2, we));
    const __m512d t2_max = mul8(_mm512_load_pd(r.len + o), nn[q]);
    __mmask8 hit = _mm512_mask_cmp_pd_mask(near[q], t1, zero, _CMP_GT_OQ);
    hit = _mm512_mask_cmp_pd_mask(hit, t1, nn[q], _CMP_LE_OQ);
    hit = _mm512_mask_cmp_pd_mask(hit, t2, zero, _CMP_GT_OQ);
    hit = _mm512_mask_cmp_pd_mask(hit, t2, t2_max, _CMP_LT_OQ);
    hit_any = static_cast<__mmask8>(hit_any | hit);
  }
  return hit_any != 0;
}

}  // namespace lmc::vis
#endif
