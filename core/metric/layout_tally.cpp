#include "core/metric/layout_tally.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

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

namespace {

// Shared by both tally_frame overloads; `cut_fingers(d, b)` gives the fingers of b (the fingers
// seeing device d sees) that have a marker beyond its axis cut.
template <typename CutFingers>
void tally_frame_with(const PreparedFrame& frame, std::span<const DeviceView> views, const FingerBits* bits,
                      const VisibilityLimits& limits, LayoutTally& t, CutFingers&& cut_fingers) {
  const int nd = static_cast<int>(views.size());
  ++t.frames;
  ++t.c[static_cast<size_t>(worst_finger_count(bits, nd))];
  FingerBits cut[kMaxDevices] = {}, inside[kMaxDevices] = {};
  for (int d = 0; d < nd; ++d) {
    const auto dd = static_cast<size_t>(d);
    cut[dd] = bits[d] != 0 ? cut_fingers(dd, bits[d]) : FingerBits{0};
    inside[dd] = static_cast<FingerBits>(bits[d] & ~cut[dd]);
  }
  ++t.c_inside_cut[static_cast<size_t>(worst_finger_count(inside, nd))];
  // Fingers seen by exactly one device: that device is the only one for them in this frame.
  FingerBits seen_once = 0, seen_twice = 0;
  for (int d = 0; d < nd; ++d) {
    seen_twice = static_cast<FingerBits>(seen_twice | (seen_once & bits[d]));
    seen_once = static_cast<FingerBits>(seen_once | bits[d]);
  }
  const auto sole = static_cast<FingerBits>(seen_once & ~seen_twice);
  for (int d = 0; d < nd; ++d) {
    const FingerBits b = bits[d];
    if (b == 0) continue;
    const auto dd = static_cast<size_t>(d);
    ++t.device_seeing_frames[dd];
    if (b & sole) ++t.device_sole_frames[dd];
    if (cut[dd] != 0) ++t.device_cut_frames[dd];
    t.device_off_centre[dd] += round_millionths(off_centre_penalty(frame, views[dd], limits) * kOffCentreScale);
  }
}

}  // namespace

void tally_frame(const PreparedFrame& frame, std::span<const DeviceView> views, const FingerBits* bits,
                 const VisibilityLimits& limits, double axis_cut_mm, LayoutTally& t) {
  tally_frame_with(frame, views, bits, limits, t, [&](size_t d, FingerBits b) {
    FingerBits c = 0;
    for (int f = 0; f < kNumDigits; ++f) {
      const auto one = static_cast<FingerBits>(1u << f);
      if ((b & one) && seen_marker_beyond_cut(frame, views[d], one, axis_cut_mm)) c = static_cast<FingerBits>(c | one);
    }
    return c;
  });
}

void tally_frame(const PreparedFrame& frame, std::span<const DeviceView> views, const FingerBits* bits,
                 const FingerBits* cut_bits, const VisibilityLimits& limits, LayoutTally& t) {
  tally_frame_with(frame, views, bits, limits, t, [&](size_t d, FingerBits b) {
    return static_cast<FingerBits>(b & cut_bits[d]);
  });
}

LayoutTally tally_layout(std::span<const DeviceView> views, std::span<const PreparedFrame> frames,
                         const VisibilityLimits& limits, double axis_cut_mm, std::span<const int> subset) {
  const int nd = static_cast<int>(views.size());
  if (nd < 1 || nd > kMaxDevices) throw Error("a layout needs 1 to 8 devices");
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
          device_visibility_with_cut(views[d], frames.subspan(begin, count), limits, axis_cut_mm,
                                     std::span<FingerBits>(bits[d], count), std::span<FingerBits>(cut[d], count));
        } else {
          for (size_t i = 0; i < count; ++i) {
            device_visibility_with_cut(views[d], frames.subspan(static_cast<size_t>(subset[begin + i]), 1), limits,
                                       axis_cut_mm, std::span<FingerBits>(&bits[d][i], 1),
                                       std::span<FingerBits>(&cut[d][i], 1));
          }
        }
      }
      for (size_t i = 0; i < count; ++i) {
        const size_t j = subset.empty() ? begin + i : static_cast<size_t>(subset[begin + i]);
        FingerBits fb[kMaxDevices] = {}, fc[kMaxDevices] = {};
        for (size_t d = 0; d < views.size(); ++d) {
          fb[d] = bits[d][i];
          fc[d] = cut[d][i];
        }
        tally_frame(frames[j], views, fb, fc, limits, t);
      }
    }
  });
  LayoutTally total(nd);
  for (const auto& t : local) total.add(t);
  return total;
}

}  // namespace lmc
