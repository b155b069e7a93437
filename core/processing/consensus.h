#pragma once
// How well a fusion keeps the hand's shape, judged without Vicon: each fused finger and
// segment length against the controllers that see that finger. Every controller reports fingers
// shorter than Vicon's markers, so Vicon alone cannot tell a fusion that shortens the hand from a
// controller that does; the controllers that see a finger can.
//
// For finger f (and each of its segments): a controller's trial mean is the mean of its length
// over the frames whose ray-traced label says it sees f (label 1, visibility_labels.h); the
// consensus is the median of those trial means over the controllers that saw f at least
// `min_seen_frames` times; the fused trial mean is over the frames where at least one such
// controller sees f and the fused length is finite. Point distance: over the same frames, the mean
// distance of each fused point of f to the same point of each seeing controller.
#include <array>
#include <vector>

#include "core/hand/hand_track.h"
#include "core/io/lmc_recording.h"
#include "core/processing/measures.h"

namespace lmc {

struct LengthConsensus {
  std::vector<double> device_mean;  // per device (NaN where the device never sees the finger)
  double median = kNaN;             // of the seeing devices' means
  double shortest = kNaN, longest = kNaN;
  double fused = kNaN;  // the fused trial mean on the frames some device sees the finger
  int seeing_devices = 0;
  double fused_minus_median() const { return fused - median; }
};

struct FingerConsensus {
  LengthConsensus finger;
  std::vector<int> segments;             // segment indices of this finger (finger_segments)
  std::vector<LengthConsensus> segment;  // one per entry of `segments`
  double point_distance_mm = kNaN;       // mean distance fused point ↔ seeing device's point
};

struct ConsensusReport {
  std::array<FingerConsensus, kNumFingers> fingers;
};

// `devices` are the world-frame tracks of the controllers (realigned, on the fused track's grid),
// `labels[d][frame]` their ray-traced labels, `fused` the fused track.
ConsensusReport consensus_report(const std::vector<DeviceTrack>& devices,
                                 const std::vector<std::vector<FingerLabels>>& labels, const HandTrack& fused,
                                 int min_seen_frames = 5);

}  // namespace lmc
