#include "core/visibility/visibility_kernel.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/common/always_inline.h"
#include "core/common/cpu_features.h"
#include "core/common/error.h"
#include "core/visibility/phalanx_block_avx512.h"
#include "core/visibility/phalanx_ring.h"
#include "core/visibility/visibility_tests.h"

namespace lmc {
namespace {

// The kernel body; compiled three times: baseline (SSE2), AVX2 and AVX-512 (dispatched at run time
// by what the CPU has, see below). The three give bit-identical results: IEEE add/mul/div are
// exact per lane, and no multiply-add is ever fused (-ffp-contract=off for every first-party file,
// cmake/lmc_target_options.cmake; AVX-512 brings FMA with it; tests/check_no_fused_multiply_add.sh
// checks the built program). Every decision uses the same expressions as the elementary tests of
// visibility_tests.h, so the bits are the explaining path's (tests check all three builds). With
// kCut it also reports, per finger, whether one of its markers lies beyond ±cut_mm on an axis of the
// device (the robust metric's axis cut): the device-frame coordinates are computed here anyway, so
// the tally need not transform the markers again. kBuild is never kBest.
template <bool kCut, KernelBuild kBuild>
LMC_ALWAYS_INLINE FingerBits visible_fingers_body(const PreparedFrame& fr, const DeviceView& d,
                                                  const VisibilityLimits& lim, double cut_mm, FingerBits* cut_bits) {
  if constexpr (kCut) *cut_bits = 0;
  if (!fr.valid) return 0;
  // Visibility step 1 approach direction.
  if (!vis::approach_ok(fr, d)) return 0;
  // Visibility step 2 range and pyramid for s1…s21: any failure hides the whole hand. Branch-free over all
  // markers (it vectorises; the seeing case, which dominates a search near the hand, has to test
  // every marker anyway), with the range test as |v|² > range_sq_exact, which decides exactly as
  // marker_in_view's sqrt(|v|²) > range (visibility_params.h). v and |v|² are kept for the rays.
  double vx[kNumRayMarkers], vy[kNumRayMarkers], vz[kNumRayMarkers], vv[kNumRayMarkers];
  std::int64_t far[kNumRayMarkers];
  std::int64_t outside = 0;
  for (int k = 1; k < kNumRayMarkers; ++k) {
    const auto kk = static_cast<size_t>(k);
    const double x = fr.mx[kk] - d.ox, y = fr.my[kk] - d.oy, z = fr.mz[kk] - d.oz;
    const double v2 = x * x + y * y + z * z;
    vx[k] = x;
    vy[k] = y;
    vz[k] = z;
    vv[k] = v2;
    const double px = d.rt[0] * x + d.rt[1] * y + d.rt[2] * z;
    const double py = d.rt[3] * x + d.rt[4] * y + d.rt[5] * z;
    const double pz = d.rt[6] * x + d.rt[7] * y + d.rt[8] * z;
    outside |= ((v2 > lim.range_sq_exact) | (v2 < lim.range_near_sq) | (std::abs(px) > py * lim.tan_half_long) |
                (std::abs(pz) > py * lim.tan_half_short))
                   ? -1
                   : 0;
    if constexpr (kCut) {
      far[k] = ((std::abs(px) > cut_mm) | (std::abs(py) > cut_mm) | (std::abs(pz) > cut_mm)) ? -1 : 0;
    }
  }
  if (outside != 0) return 0;
  vis::PhalanxRing ring;
  vis::prepare_phalanx_ring(fr, d, ring);
  // Visibility step 3 for every marker at once (vectorises, the divisions included): where the ray's line meets
  // the palm plane, t = n·(c − o) / n·v, and whether that is strictly between device and marker.
  // Same expressions as palm_occludes (visibility_tests.h); only a ray that crosses the plane needs
  // the hull test below (about a third of them).
  const double plane_num = vis::palm_plane_numerator(fr, d);
  double palm_t[kNumRayMarkers];
  std::int64_t crosses[kNumRayMarkers];
  for (int k = 1; k < kNumRayMarkers; ++k) {
    const double denom = fr.nx * vx[k] + fr.ny * vy[k] + fr.nz * vz[k];
    const double t = plane_num / denom;
    palm_t[k] = t;
    crosses[k] = ((denom != 0.0) & (t > 0.0) & (t < 1.0)) ? -1 : 0;
  }
  FingerBits bits = kAllFingersVisible;
  // Unrolled: marker indices and each finger's first ring lane become constants. (GCC's and
  // Clang's pragma; other compilers would warn of an unknown one.)
#if defined(__GNUC__)
#pragma GCC unroll 5
#endif
  for (int f = 0; f < kNumDigits; ++f) {
    const int start = vis::others_start(f);
#if defined(__GNUC__)
#pragma GCC unroll 4
#endif
    for (int j = 0; j < 4; ++j) {
      const int k = finger_marker(f, j);
      // Visibility step 3 palm (rarely hides a ray, but it is cheaper than the fingers, so it goes first);
      // Visibility step 4 the other fingers (phalanx_ring.h).
      const double t = palm_t[k];
      bool hidden = crosses[k] != 0 && hull_contains(fr.hull, d.ox + t * vx[k], d.oy + t * vy[k], d.oz + t * vz[k]);
      if (!hidden) {
#if defined(__x86_64__) && defined(__GNUC__)
        if constexpr (kBuild == KernelBuild::kAvx512) {
          hidden =
              vis::others_occlude_avx512(ring, vis::others_lane_mask(f), vx[k], vy[k], vz[k], vv[k], lim.radius_sq);
        } else {
          hidden = vis::others_occlude(ring, start, vx[k], vy[k], vz[k], vv[k], lim.radius_sq);
        }
#else
        hidden = vis::others_occlude(ring, start, vx[k], vy[k], vz[k], vv[k], lim.radius_sq);
#endif
      }
      if (hidden) {
        bits = static_cast<FingerBits>(bits & ~(1u << f));
        break;
      }
    }
  }
  if constexpr (kCut) {
    FingerBits c = 0;
    for (int f = 0; f < kNumDigits; ++f) {
      std::int64_t any = 0;
      for (int j = 0; j < 4; ++j) any |= far[finger_marker(f, j)];
      if (any != 0) c = static_cast<FingerBits>(c | (1u << f));
    }
    *cut_bits = c;
  } else {
    (void)far;
    (void)cut_mm;
    (void)cut_bits;
  }
  return bits;
}

// A device over a run of frames: the device view and limits stay in registers across frames.
template <bool kCut, KernelBuild kBuild>
LMC_ALWAYS_INLINE void device_run_body(const DeviceView& d, std::span<const PreparedFrame> frames,
                                       const VisibilityLimits& lim, double cut_mm, FingerBits* out,
                                       FingerBits* cut_out) {
  const DeviceView view = d;
  const VisibilityLimits limits = lim;
  for (size_t j = 0; j < frames.size(); ++j) {
    out[j] = visible_fingers_body<kCut, kBuild>(frames[j], view, limits, cut_mm, kCut ? cut_out + j : nullptr);
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2")]] FingerBits visible_fingers_avx2(const PreparedFrame& fr, const DeviceView& d,
                                                        const VisibilityLimits& lim) {
  return visible_fingers_body<false, KernelBuild::kAvx2>(fr, d, lim, 0.0, nullptr);
}
[[gnu::target("avx2")]] void device_run_avx2(const DeviceView& d, std::span<const PreparedFrame> frames,
                                             const VisibilityLimits& lim, FingerBits* out) {
  device_run_body<false, KernelBuild::kAvx2>(d, frames, lim, 0.0, out, nullptr);
}
[[gnu::target("avx2")]] void device_run_cut_avx2(const DeviceView& d, std::span<const PreparedFrame> frames,
                                                 const VisibilityLimits& lim, double cut_mm, FingerBits* out,
                                                 FingerBits* cut_out) {
  device_run_body<true, KernelBuild::kAvx2>(d, frames, lim, cut_mm, out, cut_out);
}
// flatten: inlines others_occlude_avx512 into the body (phalanx_block_avx512.h says why it must).
[[gnu::target("avx512f"), gnu::flatten]] FingerBits visible_fingers_avx512(const PreparedFrame& fr, const DeviceView& d,
                                                                           const VisibilityLimits& lim) {
  return visible_fingers_body<false, KernelBuild::kAvx512>(fr, d, lim, 0.0, nullptr);
}
[[gnu::target("avx512f"), gnu::flatten]] void device_run_avx512(const DeviceView& d,
                                                                std::span<const PreparedFrame> frames,
                                                                const VisibilityLimits& lim, FingerBits* out) {
  device_run_body<false, KernelBuild::kAvx512>(d, frames, lim, 0.0, out, nullptr);
}
[[gnu::target("avx512f"), gnu::flatten]] void device_run_cut_avx512(const DeviceView& d,
                                                                    std::span<const PreparedFrame> frames,
                                                                    const VisibilityLimits& lim, double cut_mm,
                                                                    FingerBits* out, FingerBits* cut_out) {
  device_run_body<true, KernelBuild::kAvx512>(d, frames, lim, cut_mm, out, cut_out);
}
#endif

// LMC_KERNEL, read once: which build kBest means. The AVX-512 build is the fastest on CPUs with
// two 512-bit multipliers (this project's machines); on CPUs with one (some laptop and entry
// server parts) the AVX2 build may be faster, and a lab can compare them with `lmc bench`.
struct KernelSetting {
  KernelBuild build = KernelBuild::kBest;
  std::string problem;
};
const KernelSetting& kernel_setting() {
  static const KernelSetting setting = [] {
    KernelSetting k;
    const char* value = std::getenv("LMC_KERNEL");
    if (value == nullptr || *value == '\0') return k;
    const std::string v(value);
    if (v == "avx512") {
      k.build = KernelBuild::kAvx512;
    } else if (v == "avx2") {
      k.build = KernelBuild::kAvx2;
    } else if (v == "baseline") {
      k.build = KernelBuild::kBaseline;
    } else {
      k.problem = "LMC_KERNEL=" + v + " is not avx512, avx2 or baseline; the fastest build runs";
    }
    return k;
  }();
  return setting;
}

// The build that runs for `wanted`: the one asked for, or the next below it the CPU has.
KernelBuild runnable_build(KernelBuild wanted) {
  if (wanted == KernelBuild::kBest) wanted = kernel_setting().build;
  if (wanted == KernelBuild::kBest || wanted == KernelBuild::kAvx512) {
    if (cpu_has_avx512()) return KernelBuild::kAvx512;
    wanted = KernelBuild::kAvx2;
  }
  if (wanted == KernelBuild::kAvx2 && cpu_has_avx2()) return KernelBuild::kAvx2;
  return KernelBuild::kBaseline;
}

void device_run_baseline(const DeviceView& d, std::span<const PreparedFrame> frames, const VisibilityLimits& lim,
                         FingerBits* out) {
  device_run_body<false, KernelBuild::kBaseline>(d, frames, lim, 0.0, out, nullptr);
}
void device_run_cut_baseline(const DeviceView& d, std::span<const PreparedFrame> frames, const VisibilityLimits& lim,
                             double cut_mm, FingerBits* out, FingerBits* cut_out) {
  device_run_body<true, KernelBuild::kBaseline>(d, frames, lim, cut_mm, out, cut_out);
}

}  // namespace

std::string kernel_setting_problem() {
  return kernel_setting().problem;
}

const char* kernel_build_name(KernelBuild build) {
  switch (runnable_build(build)) {
    case KernelBuild::kAvx512:
      return "AVX-512";
    case KernelBuild::kAvx2:
      return "AVX2";
    default:
      return "baseline";
  }
}

FingerBits visible_fingers(const PreparedFrame& fr, const DeviceView& d, const VisibilityLimits& lim,
                           KernelBuild build) {
  switch (runnable_build(build)) {
#if defined(__x86_64__) && defined(__GNUC__)
    case KernelBuild::kAvx512:
      return visible_fingers_avx512(fr, d, lim);
    case KernelBuild::kAvx2:
      return visible_fingers_avx2(fr, d, lim);
#endif
    default:
      return visible_fingers_body<false, KernelBuild::kBaseline>(fr, d, lim, 0.0, nullptr);
  }
}

void device_visibility(const DeviceView& device, std::span<const PreparedFrame> frames, const VisibilityLimits& limits,
                       std::span<FingerBits> out, KernelBuild build) {
  if (out.size() < frames.size()) throw Error("device_visibility: output shorter than the frames");
  switch (runnable_build(build)) {
#if defined(__x86_64__) && defined(__GNUC__)
    case KernelBuild::kAvx512:
      return device_run_avx512(device, frames, limits, out.data());
    case KernelBuild::kAvx2:
      return device_run_avx2(device, frames, limits, out.data());
#endif
    default:
      return device_run_baseline(device, frames, limits, out.data());
  }
}

void device_visibility_with_cut(const DeviceView& device, std::span<const PreparedFrame> frames,
                                const VisibilityLimits& limits, double axis_cut_mm, std::span<FingerBits> out,
                                std::span<FingerBits> cut_out, KernelBuild build) {
  if (out.size() < frames.size() || cut_out.size() < frames.size()) {
    throw Error("device_visibility_with_cut: output shorter than the frames");
  }
  switch (runnable_build(build)) {
#if defined(__x86_64__) && defined(__GNUC__)
    case KernelBuild::kAvx512:
      return device_run_cut_avx512(device, frames, limits, axis_cut_mm, out.data(), cut_out.data());
    case KernelBuild::kAvx2:
      return device_run_cut_avx2(device, frames, limits, axis_cut_mm, out.data(), cut_out.data());
#endif
    default:
      return device_run_cut_baseline(device, frames, limits, axis_cut_mm, out.data(), cut_out.data());
  }
}

VisibilityTable compute_visibility(std::span<const DeviceView> devices, std::span<const PreparedFrame> frames,
                                   std::span<const VisibilityLimits> limits) {
  VisibilityTable t;
  t.devices = static_cast<int>(devices.size());
  t.frames = static_cast<int>(frames.size());
  t.bits.assign(devices.size() * frames.size(), 0);
  const size_t n = frames.size();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& r) {
    const std::span<const PreparedFrame> run = frames.subspan(r.begin(), r.size());
    for (size_t d = 0; d < devices.size(); ++d) {
      device_visibility(devices[d], run, limits[d], std::span<FingerBits>(t.bits).subspan(d * n + r.begin(), r.size()));
    }
  });
  return t;
}

VisibilityTable compute_visibility(std::span<const DeviceView> devices, std::span<const PreparedFrame> frames,
                                   const VisibilityParams& params) {
  const std::vector<VisibilityLimits> limits(devices.size(), make_limits(params));
  return compute_visibility(devices, frames, limits);
}

std::vector<VisibilityLimits> device_limits(const Layout& layout, double phalanx_radius_mm) {
  std::vector<VisibilityLimits> out;
  out.reserve(layout.devices.size());
  for (const auto& d : layout.devices)
    out.push_back(make_limits(VisibilityParams::from_sensor(d.sensor, phalanx_radius_mm)));
  return out;
}

VisibilityTable compute_visibility(const Layout& layout, std::span<const PreparedFrame> frames,
                                   double phalanx_radius_mm) {
  std::vector<DeviceView> views;
  views.reserve(layout.devices.size());
  for (const auto& d : layout.devices) views.push_back(DeviceView::from_device(d));
  return compute_visibility(views, frames, device_limits(layout, phalanx_radius_mm));
}

}  // namespace lmc
