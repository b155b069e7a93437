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

// Frames per task, as in the swarm evaluator: the chunk's frames stay in cache across devices.
constexpr size_t kTallyChunkFrames = 64;

}  // namespace

LayoutTally::LayoutTally(int device_count)
    : devices(device_count),
      c(static_cast<size_t>(device_count) + 1, 0),
      device_seeing_frames(static_cast<size_t>(device_count), 0),
      device_sole_frames(static_cast<size_t>(device_count), 0),
      device_cut_frames(static_cast<size_t>(device_count), 0),
      device_off_centre(static_cast<size_t>(device_count), 0) {}

void LayoutTally::add(const LayoutTally& o) {
  frames += o.frames;
  for (size_t i = 0; i < c.size(); ++i) c[i] += o.c[i];
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

void tally_frame(const PreparedFrame& frame, std::span<const DeviceView> views, const FingerBits* bits,
                 const VisibilityLimits& limits, double axis_cut_mm, LayoutTally& t) {
  const int nd = static_cast<int>(views.size());
  ++t.frames;
  ++t.c[static_cast<size_t>(worst_finger_count(bits, nd))];
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
    if (seen_marker_beyond_cut(frame, views[dd], b, axis_cut_mm)) ++t.device_cut_frames[dd];
    t.device_off_centre[dd] += std::llround(off_centre_penalty(frame, views[dd], limits) * kOffCentreScale);
  }
}

LayoutTally tally_layout(std::span<const DeviceView> views, std::span<const PreparedFrame> frames,
                         const VisibilityLimits& limits, double axis_cut_mm, std::span<const int> subset) {
  const int nd = static_cast<int>(views.size());
  if (nd < 1 || nd > kMaxDevices) throw Error("a layout needs 1 to 8 devices");
  const size_t n = subset.empty() ? frames.size() : subset.size();
  tbb::enumerable_thread_specific<LayoutTally> local([&] { return LayoutTally(nd); });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kTallyChunkFrames), [&](const tbb::blocked_range<size_t>& r) {
    LayoutTally& t = local.local();
    for (size_t jj = r.begin(); jj != r.end(); ++jj) {
      const size_t j = subset.empty() ? jj : static_cast<size_t>(subset[jj]);
      FingerBits bits[kMaxDevices] = {};
      for (size_t d = 0; d < views.size(); ++d) bits[d] = visible_fingers(frames[j], views[d], limits);
      tally_frame(frames[j], views, bits, limits, axis_cut_mm, t);
    }
  });
  LayoutTally total(nd);
  for (const auto& t : local) total.add(t);
  return total;
}

}  // namespace lmc
