#include "core/metric/layout_tally.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/common/error.h"
#include "core/layout/layout.h"
#include "core/metric/coverage.h"

namespace lmc {
namespace {

struct TallyDeviceFrame {
  double x, y, z;
};

TallyDeviceFrame tally_to_device(const DeviceView& v, double wx, double wy, double wz) {
  const double dx = wx - v.ox, dy = wy - v.oy, dz = wz - v.oz;
  return {v.rt[0] * dx + v.rt[1] * dy + v.rt[2] * dz, v.rt[3] * dx + v.rt[4] * dy + v.rt[5] * dz,
          v.rt[6] * dx + v.rt[7] * dy + v.rt[8] * dz};
}

// std::llround for the off-centre penalty in millionths (0 … 10⁶) without a libm call per seeing
// pair: for 0 ≤ x < 2⁵² the cast truncates exactly and x − trunc(x) is exact, so adding one when
// that is ≥ 0.5 rounds half away from zero, as llround does. Anything else goes to llround.
std::int64_t round_millionths(double x) {
  if (!(x >= 0.0 && x < 0x1.0p52)) return std::llround(x);
  const auto i = static_cast<std::int64_t>(x);
  return i + (x - static_cast<double>(i) >= 0.5 ? 1 : 0);
}

// Frames per task, as in the swarm evaluator: the chunk's frames stay in cache across devices.
constexpr size_t kTallyChunkFrames = 64;

}  // namespace

LayoutTally::LayoutTally(int device_count)
    : devices(device_count),
      c(static_cast<size_t>(device_count) + 1, 0),
      c_inside_cut(static_cast<size_t>(device_count) + 1, 0),
      device_seeing_frames(static_cast<size_t>(device_count), 0),
      device_sole_frames(static_cast<size_t>(device_count), 0),
      device_cut_frames(static_cast<size_t>(device_count), 0),
      device_off_centre(static_cast<size_t>(device_count), 0) {}

void LayoutTally::add(const LayoutTally& o) {
  frames += o.frames;
  for (size_t i = 0; i < c.size(); ++i) {
    c[i] += o.c[i];
    c_inside_cut[i] += o.c_inside_cut[i];
  }
  for (size_t d = 0; d < device_seeing_frames.size(); ++d) {
    device_seeing_frames[d] += o.device_seeing_frames[d];
    device_sole_frames[d] += o.device_sole_frames[d];
    device_cut_frames[d] += o.device_cut_frames[d];
    device_off_centre[d] += o.device_off_centre[d];
  }
}

std::int64_t LayoutTally::seeing_pairs() const {
  std::int64_t s = 0;
  for (const auto v : device_seeing_frames) s += v;
  return s;
}

std::int64_t LayoutTally::cut_pairs() const {
  std::int64_t s = 0;
  for (const auto v : device_cut_frames) s += v;
  return s;
}

std::int64_t LayoutTally::off_centre_sum() const {
  std::int64_t s = 0;
  for (const auto v : device_off_centre) s += v;
  return s;
}

bool seen_marker_beyond_cut(const PreparedFrame& f, const DeviceView& v, FingerBits bits, double cut) {
  for (int finger = 0; finger < kNumDigits; ++finger) {
    if (!((bits >> finger) & 1)) continue;
    for (int j = 0; j < 4; ++j) {
      const auto k = static_cast<size_t>(finger_marker(finger, j));
      const TallyDeviceFrame p = tally_to_device(v, f.mx[k], f.my[k], f.mz[k]);
      if (std::abs(p.x) > cut || std::abs(p.y) > cut || std::abs(p.z) > cut) return true;
    }
  }
  return false;
}

double off_centre_penalty(const PreparedFrame& f, const DeviceView& v, const VisibilityLimits& lim) {
  const TallyDeviceFrame p = tally_to_device(v, f.cx, f.cy, f.cz);
  if (!(p.y > 0.0)) return 1.0;  // behind or level with the controller: as far off-centre as it gets
  const double tx = std::abs(p.x) / (p.y * lim.tan_half_long);
  const double tz = std::abs(p.z) / (p.y * lim.tan_half_short);
  return std::min(1.0, 0.5 * (tx * tx + tz * tz));
}

// Frames counted together by tally_frames: byte arrays of this many frames stay in registers or L1.
constexpr size_t kTallyBlockFrames = 64;

std::vector<VisibilityLimits> same_limits(const VisibilityLimits& limits, size_t devices, double axis_cut_mm) {
  std::vector<VisibilityLimits> out(devices, limits);
  if (axis_cut_mm >= 0) {
    for (auto& l : out) l.axis_cut_mm = axis_cut_mm;
  }
  return out;
}

void tally_frames(std::span<const PreparedFrame> frames, std::span<const DeviceView> views, const FingerBits* bits,
                  const FingerBits* cut_bits, size_t stride, const VisibilityLimits& limits, LayoutTally& t) {
  VisibilityLimits each[kMaxDevices];
  for (size_t d = 0; d < views.size() && d < static_cast<size_t>(kMaxDevices); ++d) each[d] = limits;
  tally_frames(frames, views, bits, cut_bits, stride,
               std::span<const VisibilityLimits>(each, std::min(views.size(), static_cast<size_t>(kMaxDevices))), t);
}

void tally_frames(std::span<const PreparedFrame> frames, std::span<const DeviceView> views, const FingerBits* bits,
                  const FingerBits* cut_bits, size_t stride, std::span<const VisibilityLimits> limits, LayoutTally& t) {
  const size_t nd = views.size();
  if (nd < 1 || nd > static_cast<size_t>(kMaxDevices)) throw Error("a layout needs 1 to 8 devices");
  if (limits.size() != nd) throw Error("tally_frames: one limits entry per device");
  if (t.c.size() != nd + 1) throw Error("tally_frames: the tally is for another number of devices");
  for (size_t b0 = 0; b0 < frames.size(); b0 += kTallyBlockFrames) {
    const size_t m = std::min(kTallyBlockFrames, frames.size() - b0);
    // Per frame and finger: how many devices see it, all markers counted and only those inside
    // the cut (a finger with a marker beyond a device's cut is unseen by it, layout_tally.h); and
    // the fingers seen by at least one device and by two or more. Loops over frames of bytes,
    // which the compiler vectorises.
    alignas(64) std::uint8_t seeing[kNumDigits][kTallyBlockFrames] = {};
    alignas(64) std::uint8_t seeing_inside[kNumDigits][kTallyBlockFrames] = {};
    alignas(64) std::uint8_t once[kTallyBlockFrames] = {}, twice[kTallyBlockFrames] = {};
    for (size_t d = 0; d < nd; ++d) {
      const FingerBits* const b = bits + d * stride + b0;
      const FingerBits* const c = cut_bits + d * stride + b0;
      for (size_t j = 0; j < m; ++j) {
        const std::uint8_t seen = b[j], inside = static_cast<std::uint8_t>(b[j] & ~c[j]);
        twice[j] = static_cast<std::uint8_t>(twice[j] | (once[j] & seen));
        once[j] = static_cast<std::uint8_t>(once[j] | seen);
        for (int k = 0; k < kNumDigits; ++k) {
          seeing[k][j] = static_cast<std::uint8_t>(seeing[k][j] + ((seen >> k) & 1));
          seeing_inside[k][j] = static_cast<std::uint8_t>(seeing_inside[k][j] + ((inside >> k) & 1));
        }
      }
    }
    // The study's histogram: the devices seeing each frame's worst-covered finger (coverage.h's
    // worst_finger_count, the same minimum), once as seen and once inside the cuts.
    for (size_t j = 0; j < m; ++j) {
      std::uint8_t worst = seeing[0][j], worst_inside = seeing_inside[0][j];
      for (int k = 1; k < kNumDigits; ++k) {
        worst = std::min(worst, seeing[k][j]);
        worst_inside = std::min(worst_inside, seeing_inside[k][j]);
      }
      ++t.c[worst];
      ++t.c_inside_cut[worst_inside];
    }
    // Per device: frames it sees in, frames it alone sees some finger in (fingers seen by exactly
    // one device), frames with a seen marker beyond its cut, and where the palm sits in its view.
    for (size_t d = 0; d < nd; ++d) {
      const FingerBits* const b = bits + d * stride + b0;
      const FingerBits* const c = cut_bits + d * stride + b0;
      std::int64_t seeing_frames = 0, sole_frames = 0, cut_frames = 0, off_centre = 0;
      for (size_t j = 0; j < m; ++j) {
        const auto sole = static_cast<std::uint8_t>(once[j] & ~twice[j]);
        seeing_frames += b[j] != 0;
        sole_frames += (b[j] & sole) != 0;
        cut_frames += (b[j] & c[j]) != 0;
      }
      for (size_t j = 0; j < m; ++j) {
        if (b[j] != 0)
          off_centre += round_millionths(off_centre_penalty(frames[b0 + j], views[d], limits[d]) * kOffCentreScale);
      }
      t.device_seeing_frames[d] += seeing_frames;
      t.device_sole_frames[d] += sole_frames;
      t.device_cut_frames[d] += cut_frames;
      t.device_off_centre[d] += off_centre;
    }
  }
  t.frames += static_cast<std::int64_t>(frames.size());
}

void tally_frame(const PreparedFrame& frame, std::span<const DeviceView> views, const FingerBits* bits,
                 const VisibilityLimits& limits, double axis_cut_mm, LayoutTally& t) {
  FingerBits cut[kMaxDevices] = {};
  for (size_t d = 0; d < views.size() && d < static_cast<size_t>(kMaxDevices); ++d) {
    for (int f = 0; f < kNumDigits; ++f) {
      const auto one = static_cast<FingerBits>(1u << f);
      if ((bits[d] & one) && seen_marker_beyond_cut(frame, views[d], one, axis_cut_mm)) {
        cut[d] = static_cast<FingerBits>(cut[d] | one);
      }
    }
  }
  tally_frames(std::span<const PreparedFrame>(&frame, 1), views, bits, cut, 1, limits, t);
}

void tally_frame(const PreparedFrame& frame, std::span<const DeviceView> views, const FingerBits* bits,
                 const FingerBits* cut_bits, const VisibilityLimits& limits, LayoutTally& t) {
  tally_frames(std::span<const PreparedFrame>(&frame, 1), views, bits, cut_bits, 1, limits, t);
}

void tally_frame(const PreparedFrame& frame, std::span<const DeviceView> views, const FingerBits* bits,
                 const FingerBits* cut_bits, std::span<const VisibilityLimits> limits, LayoutTally& t) {
  tally_frames(std::span<const PreparedFrame>(&frame, 1), views, bits, cut_bits, 1, limits, t);
}

LayoutTally tally_layout(std::span<const DeviceView> views, std::span<const PreparedFrame> frames,
                         const VisibilityLimits& limits, double axis_cut_mm, std::span<const int> subset) {
  return tally_layout(views, frames, same_limits(limits, views.size(), axis_cut_mm), subset);
}

LayoutTally tally_layout(std::span<const DeviceView> views, std::span<const PreparedFrame> frames,
                         std::span<const VisibilityLimits> limits, std::span<const int> subset) {
  const int nd = static_cast<int>(views.size());
  if (nd < 1 || nd > kMaxDevices) throw Error("a layout needs 1 to 8 devices");
  if (limits.size() != views.size()) throw Error("tally_layout: one limits entry per device");
  const size_t n = subset.empty() ? frames.size() : subset.size();
  tbb::enumerable_thread_specific<LayoutTally> local([&] { return LayoutTally(nd); });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kTallyChunkFrames), [&](const tbb::blocked_range<size_t>& r) {
    LayoutTally& t = local.local();
    FingerBits bits[kMaxDevices][kTallyChunkFrames];
    FingerBits cut[kMaxDevices][kTallyChunkFrames];
    for (size_t begin = r.begin(); begin < r.end(); begin += kTallyChunkFrames) {
      const size_t count = std::min(r.end() - begin, kTallyChunkFrames);
      // Each device over the run of frames (one kernel call per run); with a subset, frame by frame.
      for (size_t d = 0; d < views.size(); ++d) {
        if (subset.empty()) {
          device_visibility_with_cut(views[d], frames.subspan(begin, count), limits[d], limits[d].axis_cut_mm,
                                     std::span<FingerBits>(bits[d], count), std::span<FingerBits>(cut[d], count));
        } else {
          for (size_t i = 0; i < count; ++i) {
            device_visibility_with_cut(views[d], frames.subspan(static_cast<size_t>(subset[begin + i]), 1), limits[d],
                                       limits[d].axis_cut_mm, std::span<FingerBits>(&bits[d][i], 1),
                                       std::span<FingerBits>(&cut[d][i], 1));
          }
        }
      }
      if (subset.empty()) {
        tally_frames(frames.subspan(begin, count), views, &bits[0][0], &cut[0][0], kTallyChunkFrames, limits, t);
        continue;
      }
      for (size_t i = 0; i < count; ++i) {
        FingerBits fb[kMaxDevices] = {}, fc[kMaxDevices] = {};
        for (size_t d = 0; d < views.size(); ++d) {
          fb[d] = bits[d][i];
          fc[d] = cut[d][i];
        }
        tally_frame(frames[static_cast<size_t>(subset[begin + i])], views, fb, fc, limits, t);
      }
    }
  });
  LayoutTally total(nd);
  for (const auto& t : local) total.add(t);
  return total;
}

}  // namespace lmc
