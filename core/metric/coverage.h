#pragma once
// The numbers behind the placement metric (docs/algorithms/metric.md), computed from the
// visibility bits of a layout: for frame j and finger k, count the devices that see k;
// F_j = min over the five fingers; c_i = #{j : F_j = i} for i = 0…D; plus per device × finger
// coverage and per finger "seen by nobody" counts.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/hand/hand_frame.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc {

struct Coverage {
  int devices = 0;
  std::int64_t frames = 0;
  std::vector<std::int64_t> c;  // size devices + 1: c[i] = frames whose worst finger is seen by i devices
  // device_finger_seen[d][k]: frames in which device d sees finger k.
  std::vector<std::array<std::int64_t, kNumDigits>> device_finger_seen;
  // Frames in which no device sees finger k.
  std::array<std::int64_t, kNumDigits> finger_unseen{};
  double metric = 0.0;  // M (placement_metric.h)

  // Fraction helpers for tables (0 when there are no frames).
  double device_finger_fraction(int device, int finger) const;
  double finger_unseen_fraction(int finger) const;
};

// All frames, or only `frame_subset` (indices into the table's frames) when it is non-empty
// (e.g. the horizontal poses).
Coverage compute_coverage(const VisibilityTable& table, std::span<const int> frame_subset = {});

// The same from per-device bit columns (each of the same length), for callers that cache
// columns per device (the workbench while dragging one device).
Coverage compute_coverage(std::span<const std::span<const FingerBits>> device_columns,
                          std::span<const int> frame_subset = {});

// Coverage of all frames and of each palm orientation's frames (the split the paper reports and
// `lmc evaluate`, the Coverage panel and the Optimiser's comparison all show). An orientation
// with no frames gets an empty Coverage (0 frames), never all frames: compute_coverage reads an
// empty subset as "all".
struct OrientationCoverage {
  Coverage all, horizontal, vertical;
};
OrientationCoverage coverage_by_orientation(std::span<const std::span<const FingerBits>> device_columns,
                                            std::span<const int> horizontal, std::span<const int> vertical);
OrientationCoverage coverage_by_orientation(const VisibilityTable& table, std::span<const int> horizontal,
                                            std::span<const int> vertical);

// Each finger bit of a FingerBits value moved to its own byte (finger k → byte k), so that adding
// these for up to 255 devices counts the devices that see each finger in one integer addition per
// device, without carries between the bytes.
inline constexpr std::array<std::uint64_t, 32> kFingerBytes = [] {
  std::array<std::uint64_t, 32> t{};
  for (unsigned b = 0; b < 32; ++b) {
    for (unsigned k = 0; k < static_cast<unsigned>(kNumDigits); ++k)
      t[b] |= static_cast<std::uint64_t>((b >> k) & 1u) << (8 * k);
  }
  return t;
}();

// Number of devices that see the worst-covered finger, given the bits of each device for one
// frame: min over fingers of the per-finger counts. Called once per (layout, frame) in the search,
// hence the byte-wise counting (the same integers as counting finger by finger).
inline int worst_finger_count(const FingerBits* bits, int devices) {
  if (devices > 255) {
    int counts[kNumDigits] = {0, 0, 0, 0, 0};
    for (int d = 0; d < devices; ++d) {
      for (int k = 0; k < kNumDigits; ++k) counts[k] += (bits[d] >> k) & 1;
    }
    int m = counts[0];
    for (int k = 1; k < kNumDigits; ++k) m = counts[k] < m ? counts[k] : m;
    return m;
  }
  std::uint64_t sum = 0;
  for (int d = 0; d < devices; ++d) sum += kFingerBytes[bits[d] & 0x1Fu];
  int m = static_cast<int>(sum & 0xFFu);
  for (int k = 1; k < kNumDigits; ++k) {
    const int c = static_cast<int>((sum >> (8 * k)) & 0xFFu);
    m = c < m ? c : m;
  }
  return m;
}

}  // namespace lmc
