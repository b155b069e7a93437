#pragma once
// The fast face of the visibility test (docs/algorithms/visibility.md): 5 bits per (device, frame),
// bit k set when finger k (0 thumb … 4 pinky) is visible. Uses the same elementary tests as
// visibility_explain.h (visibility_tests.h), with early exits.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/layout/layout.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

using FingerBits = std::uint8_t;
inline constexpr FingerBits kAllFingersVisible = 0x1F;

// The kernel is built three times, bit-identical (visibility_kernel.cpp): baseline (SSE2), AVX2
// and AVX-512. kBest runs the fastest this CPU has, or the build the environment variable
// LMC_KERNEL names (avx512, avx2, baseline); a named build is for tests that check the builds agree
// and for benchmarks. A build the CPU lacks falls back to the next below it.
enum class KernelBuild { kBest, kAvx512, kAvx2, kBaseline };
// A build's name ("AVX-512", "AVX2", "baseline"); for kBest, or a build the CPU lacks, the name of
// the build that runs.
const char* kernel_build_name(KernelBuild build);
// What is wrong with LMC_KERNEL ("" when it is unset or valid), for programs to say so.
std::string kernel_setting_problem();

// One (device, frame).
FingerBits visible_fingers(const PreparedFrame& frame, const DeviceView& device, const VisibilityLimits& limits,
                           KernelBuild build = KernelBuild::kBest);

// One device over many frames (the workbench caches these per-device columns; the swarm
// evaluator runs it per chunk of frames). Dispatches once per call, not per frame. `out` holds at
// least frames.size() entries.
void device_visibility(const DeviceView& device, std::span<const PreparedFrame> frames, const VisibilityLimits& limits,
                       std::span<FingerBits> out, KernelBuild build = KernelBuild::kBest);

// The same bits, plus per frame the fingers that have a marker beyond ±axis_cut_mm on an axis of
// the device (bit f as in FingerBits; 0 where the device sees nothing). The robust metric's axis
// cut counts a seeing (device, frame) pair when bits & cut_bits is not 0, exactly as
// seen_marker_beyond_cut (layout_tally.h) decides it.
void device_visibility_with_cut(const DeviceView& device, std::span<const PreparedFrame> frames,
                                const VisibilityLimits& limits, double axis_cut_mm, std::span<FingerBits> out,
                                std::span<FingerBits> cut_bits, KernelBuild build = KernelBuild::kBest);

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
// result does not depend on the thread count). Each device sees through its own sensor model.
VisibilityTable compute_visibility(const Layout& layout, std::span<const PreparedFrame> frames,
                                   double phalanx_radius_mm = 10.0);
VisibilityTable compute_visibility(std::span<const DeviceView> devices, std::span<const PreparedFrame> frames,
                                   const VisibilityParams& params);
// Each device through its own limits (limits[d] for devices[d]): a mixed rig.
VisibilityTable compute_visibility(std::span<const DeviceView> devices, std::span<const PreparedFrame> frames,
                                   std::span<const VisibilityLimits> limits);

// Each device's limits from its own sensor model (LayoutDevice::sensor), in layout order.
std::vector<VisibilityLimits> device_limits(const Layout& layout, double phalanx_radius_mm = 10.0);

}  // namespace lmc
