#include "core/visibility/visibility_kernel.h"

#include <tbb/parallel_for.h>

#include "core/visibility/visibility_tests.h"

namespace lmc {
namespace {

// Phalanges that may hide finger f: all but its own three (bit p = phalanx p).
constexpr std::uint16_t other_phalanges(int f) {
  return static_cast<std::uint16_t>(0x7FFF & ~(0x7u << (3 * f)));
}

}  // namespace

FingerBits visible_fingers(const PreparedFrame& fr, const DeviceView& d, const VisibilityLimits& lim) {
  if (!fr.valid) return 0;
  // §3.1 approach direction.
  if (!vis::approach_ok(fr, d)) return 0;
  // §3.2 range and pyramid for s1…s21: any failure hides the whole hand.
  for (int k = 1; k < kNumRayMarkers; ++k) {
    const auto kk = static_cast<size_t>(k);
    if (vis::marker_in_view(fr.mx[kk], fr.my[kk], fr.mz[kk], d, lim) != vis::ViewResult::kInside) return 0;
  }
  // Device-relative phalanx bases, shared by all rays.
  alignas(64) double ex[16], ey[16], ez[16];
  for (int p = 0; p < kNumPhalanges; ++p) {
    const auto pp = static_cast<size_t>(p);
    ex[p] = fr.bx[pp] - d.ox;
    ey[p] = fr.by[pp] - d.oy;
    ez[p] = fr.bz[pp] - d.oz;
  }
  const double plane_num = vis::palm_plane_numerator(fr, d);
  FingerBits bits = kAllFingersVisible;
  for (int f = 0; f < kNumDigits; ++f) {
    const std::uint16_t others = other_phalanges(f);
    for (int j = 0; j < 4; ++j) {
      const auto k = static_cast<size_t>(finger_marker(f, j));
      const double vx = fr.mx[k] - d.ox, vy = fr.my[k] - d.oy, vz = fr.mz[k] - d.oz;
      // §3.3 palm.
      bool hidden = vis::palm_occludes(fr, d, plane_num, vx, vy, vz);
      // §3.4 other fingers: evaluate all 15 branch-free (vectorises), keep the others' bits.
      if (!hidden) {
        unsigned hits = 0;
        for (int p = 0; p < kNumPhalanges; ++p) {
          const auto pp = static_cast<size_t>(p);
          hits |= static_cast<unsigned>(vis::phalanx_occludes(ex[p], ey[p], ez[p], fr.wx[pp], fr.wy[pp], fr.wz[pp],
                                                              fr.len[pp], vx, vy, vz, lim.radius_sq))
                  << p;
        }
        hidden = (hits & others) != 0;
      }
      if (hidden) {
        bits = static_cast<FingerBits>(bits & ~(1u << f));
        break;
      }
    }
  }
  return bits;
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
