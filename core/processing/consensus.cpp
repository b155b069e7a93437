#include "core/processing/consensus.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace lmc {
namespace {

double consensus_median(std::vector<double> v) {
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

bool device_sees(const std::vector<std::vector<FingerLabels>>& labels, size_t d, int frame, int finger) {
  return d < labels.size() && static_cast<size_t>(frame) < labels[d].size() &&
         labels[d][static_cast<size_t>(frame)][static_cast<size_t>(finger)] == 1;
}

// Trial means over the frames a device sees `finger`; `length(track, frame)` measures one frame.
template <typename Length>
LengthConsensus length_consensus(const std::vector<DeviceTrack>& devices,
                                 const std::vector<std::vector<FingerLabels>>& labels, const HandTrack& fused,
                                 int finger, int min_seen, Length length) {
  LengthConsensus c;
  c.device_mean.assign(devices.size(), kNaN);
  std::vector<bool> counts(devices.size(), false);
  std::vector<double> means;
  for (size_t d = 0; d < devices.size(); ++d) {
    double sum = 0;
    int n = 0;
    for (int f = 0; f < devices[d].track.frame_count; ++f) {
      if (!device_sees(labels, d, f, finger)) continue;
      const double v = length(devices[d].track, f);
      if (!std::isfinite(v)) continue;
      sum += v;
      ++n;
    }
    if (n > 0) c.device_mean[d] = sum / n;
    if (n >= min_seen) {
      counts[d] = true;
      means.push_back(sum / n);
    }
  }
  c.seeing_devices = static_cast<int>(means.size());
  c.median = consensus_median(means);
  if (!means.empty()) {
    c.shortest = *std::min_element(means.begin(), means.end());
    c.longest = *std::max_element(means.begin(), means.end());
  }
  double sum = 0;
  int n = 0;
  for (int f = 0; f < fused.frame_count; ++f) {
    bool seen = false;
    for (size_t d = 0; d < devices.size() && !seen; ++d) seen = counts[d] && device_sees(labels, d, f, finger);
    if (!seen) continue;
    const double v = length(fused, f);
    if (!std::isfinite(v)) continue;
    sum += v;
    ++n;
  }
  if (n > 0) c.fused = sum / n;
  return c;
}

double consensus_segment_length(const HandTrack& t, int frame, int segment) {
  const auto p = segment_points(segment);
  return (t.at(frame, p[1]) - t.at(frame, p[0])).norm();
}

}  // namespace

ConsensusReport consensus_report(const std::vector<DeviceTrack>& devices,
                                 const std::vector<std::vector<FingerLabels>>& labels, const HandTrack& fused,
                                 int min_seen_frames) {
  ConsensusReport r;
  for (int finger = 0; finger < kNumFingers; ++finger) {
    FingerConsensus& fc = r.fingers[static_cast<size_t>(finger)];
    const std::span<const int> segments = finger_segments(finger);
    fc.segments.assign(segments.begin(), segments.end());
    fc.finger = length_consensus(devices, labels, fused, finger, min_seen_frames, [&](const HandTrack& t, int f) {
      double sum = 0;
      for (const int s : fc.segments) sum += consensus_segment_length(t, f, s);
      return sum;
    });
    for (const int s : fc.segments) {
      fc.segment.push_back(
          length_consensus(devices, labels, fused, finger, min_seen_frames,
                           [s](const HandTrack& t, int f) { return consensus_segment_length(t, f, s); }));
    }
    // The finger's points, each once.
    std::set<int> points;
    for (const int s : fc.segments) {
      const auto p = segment_points(s);
      points.insert(p[0]);
      points.insert(p[1]);
    }
    double sum = 0;
    long n = 0;
    for (size_t d = 0; d < devices.size(); ++d) {
      for (int f = 0; f < std::min(devices[d].track.frame_count, fused.frame_count); ++f) {
        if (!device_sees(labels, d, f, finger)) continue;
        for (const int p : points) {
          const double dist = (fused.at(f, p) - devices[d].track.at(f, p)).norm();
          if (!std::isfinite(dist)) continue;
          sum += dist;
          ++n;
        }
      }
    }
    if (n > 0) fc.point_distance_mm = sum / static_cast<double>(n);
  }
  return r;
}

}  // namespace lmc
