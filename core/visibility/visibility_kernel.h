#pragma once
// The fast face of the visibility test (reference-algorithms.md §3): 5 bits per (device, frame),
// bit k set when finger k (0 thumb … 4 pinky) is visible. Uses the same elementary tests as
// visibility_explain.h (visibility_tests.h), with early exits.
#include <cstdint>
#include <span>
#include <vector>

#include "core/layout/layout.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

using FingerBits = std::uint8_t;
inline constexpr FingerBits kAllFingersVisible = 0x1F;

// One (device, frame). On x86-64 CPUs with AVX2 this runs an AVX2 build of the same code (no
// fused multiply-add, so the results are bit-identical to the baseline build).
FingerBits visible_fingers(const PreparedFrame& frame, const DeviceView& device, const VisibilityLimits& limits);
// The baseline (SSE2) build of the same kernel, for tests that check the two builds agree.
FingerBits visible_fingers_baseline(const PreparedFrame& frame, const DeviceView& device, const VisibilityLimits& limits);

// One device over many frames (the workbench caches these per-device columns; the swarm
// evaluator runs it per chunk of frames). Dispatches once per call, not per frame. `out` holds at
// least frames.size() entries.
void device_visibility(const DeviceView& device, std::span<const PreparedFrame> frames,
                       const VisibilityLimits& limits, std::span<FingerBits> out);

// The same bits, plus per frame the fingers that have a marker beyond ±axis_cut_mm on an axis of
// the device (bit f as in FingerBits; 0 where the device sees nothing). The robust metric's axis
// cut counts a seeing (device, frame) pair when bits & cut_bits is not 0, exactly as
// seen_marker_beyond_cut (layout_tally.h) decides it. `allow_avx2 = false` runs the baseline build
// (for tests that check the two agree).
void device_visibility_with_cut(const DeviceView& device, std::span<const PreparedFrame> frames,
                                const VisibilityLimits& limits, double axis_cut_mm, std::span<FingerBits> out,
                                std::span<FingerBits> cut_bits, bool allow_avx2 = true);

// D × N bits for a layout: bits[d·N + j] (device-major).
struct VisibilityTable {
  int devices = 0;
  int frames = 0;
  std::vector<FingerBits> bits;

  FingerBits at(int device, int frame) const {
    return bits[static_cast<size_t>(device) * static_cast<size_t>(frames) + static_cast<size_t>(frame)];
  }
  std::span<const FingerBits> device_column(int device) const {
    return std::span<const FingerBits>(bits).subspan(static_cast<size_t>(device) * static_cast<size_t>(frames),
                                                     static_cast<size_t>(frames));
  }
};

// Evaluates every device of `layout` on every frame (parallel over frames with oneTBB; the
// result does not depend on the thread count). The sensor model comes from the layout.
VisibilityTable compute_visibility(const Layout& layout, std::span<const PreparedFrame> frames,
                                   double phalanx_radius_mm = 10.0);
VisibilityTable compute_visibility(std::span<const DeviceView> devices, std::span<const PreparedFrame> frames,
                                   const VisibilityParams& params);

}  // namespace lmc
