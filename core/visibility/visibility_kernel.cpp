#include "core/visibility/visibility_kernel.h"

#include <tbb/parallel_for.h>

#include "core/visibility/visibility_tests.h"

namespace lmc {
namespace {

// Per finger f, lane mask of the phalanges that may hide it: all but its own three (and not the
// dummy 16th lane).
struct OtherMasks {
  alignas(64) std::int64_t m[kNumDigits][vis::kPhalanxLanes];
};
constexpr OtherMasks make_other_masks() {
  OtherMasks o{};
  for (int f = 0; f < kNumDigits; ++f) {
    for (int p = 0; p < vis::kPhalanxLanes; ++p) o.m[f][p] = (p < kNumPhalanges && p / 3 != f) ? -1 : 0;
  }
  return o;
}
constexpr OtherMasks kOtherMasks = make_other_masks();

// The kernel body; compiled twice (baseline and AVX2, see below). No fused multiply-add is
// enabled, so both builds give bit-identical results (IEEE add/mul are exact per lane).
[[gnu::always_inline]] inline FingerBits visible_fingers_body(const PreparedFrame& fr, const DeviceView& d,
                                                            const VisibilityLimits& lim) {
  if (!fr.valid) return 0;
  // §3.1 approach direction.
  if (!vis::approach_ok(fr, d)) return 0;
  // §3.2 range and pyramid for s1…s21: any failure hides the whole hand.
  for (int k = 1; k < kNumRayMarkers; ++k) {
    const auto kk = static_cast<size_t>(k);
    if (vis::marker_in_view(fr.mx[kk], fr.my[kk], fr.mz[kk], d, lim) != vis::ViewResult::kInside) return 0;
  }
  vis::PhalanxBlock pb;
  vis::prepare_phalanges(fr, d, pb);
  const double plane_num = vis::palm_plane_numerator(fr, d);
  FingerBits bits = kAllFingersVisible;
  for (int f = 0; f < kNumDigits; ++f) {
    const std::int64_t* others = kOtherMasks.m[f];
    for (int j = 0; j < 4; ++j) {
      const auto k = static_cast<size_t>(finger_marker(f, j));
      const double vx = fr.mx[k] - d.ox, vy = fr.my[k] - d.oy, vz = fr.mz[k] - d.oz;
      // §3.3 palm.
      bool hidden = vis::palm_occludes(fr, d, plane_num, vx, vy, vz);
      // §3.4 other fingers: all 16 lanes branch-free (vectorises), masked to the other fingers.
      if (!hidden) {
        const double vv = vx * vx + vy * vy + vz * vz;
        std::int64_t any = 0;
        for (int p = 0; p < vis::kPhalanxLanes; ++p) {
          const std::int64_t hit = vis::phalanx_occludes(pb, p, vx, vy, vz, vv, lim.radius_sq) ? -1 : 0;
          any |= hit & others[p];
        }
        hidden = any != 0;
      }
      if (hidden) {
        bits = static_cast<FingerBits>(bits & ~(1u << f));
        break;
      }
    }
  }
  return bits;
}

#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2")]] FingerBits visible_fingers_avx2(const PreparedFrame& fr, const DeviceView& d,
                                                       const VisibilityLimits& lim) {
  return visible_fingers_body(fr, d, lim);
}
bool has_avx2() {
  static const bool yes = [] {
    __builtin_cpu_init();  // needed when first used from a static initialiser
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return yes;
}
#endif

}  // namespace

FingerBits visible_fingers_baseline(const PreparedFrame& fr, const DeviceView& d, const VisibilityLimits& lim) {
  return visible_fingers_body(fr, d, lim);
}

FingerBits visible_fingers(const PreparedFrame& fr, const DeviceView& d, const VisibilityLimits& lim) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (has_avx2()) return visible_fingers_avx2(fr, d, lim);
#endif
  return visible_fingers_baseline(fr, d, lim);
}

void device_visibility(const DeviceView& device, std::span<const PreparedFrame> frames, const VisibilityLimits& limits,
                       std::span<FingerBits> out) {
  for (size_t j = 0; j < frames.size(); ++j) out[j] = visible_fingers(frames[j], device, limits);
}

VisibilityTable compute_visibility(std::span<const DeviceView> devices, std::span<const PreparedFrame> frames,
                                   const VisibilityParams& params) {
  VisibilityTable t;
  t.devices = static_cast<int>(devices.size());
  t.frames = static_cast<int>(frames.size());
  t.bits.assign(devices.size() * frames.size(), 0);
  const VisibilityLimits lim = make_limits(params);
  const size_t n = frames.size();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t d = 0; d < devices.size(); ++d) {
      for (size_t j = r.begin(); j != r.end(); ++j) t.bits[d * n + j] = visible_fingers(frames[j], devices[d], lim);
    }
  });
  return t;
}

VisibilityTable compute_visibility(const Layout& layout, std::span<const PreparedFrame> frames,
                                   double phalanx_radius_mm) {
  std::vector<DeviceView> views;
  views.reserve(layout.devices.size());
  for (const auto& d : layout.devices) views.push_back(DeviceView::from_device(d));
  return compute_visibility(views, frames, VisibilityParams::from_sensor(layout.sensor, phalanx_radius_mm));
}

}  // namespace lmc
