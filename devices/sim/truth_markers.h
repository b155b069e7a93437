#pragma once
// Ground truth as a Vicon-style marker set: the exact inverse of the mapping in
// assets/mappings/vicon-26-to-lmc.json (docs/algorithms/vicon.md), so that a simulated TRC
// mapped back with that file gives the truth hand's points.
//  * A marker that some point copies with weight 1 is that point (palm = Hand4, elbow = Forearm1,
//    thumb Meta = Proxi = Hand2, index Meta = Hand3, pinky Meta = Hand1, phalanx markers …).
//  * Two markers averaged into one point and used nowhere else (wrist = mean(Forearm2, Forearm3))
//    straddle that point ±25 mm along the palm's lateral axis, as the styloid markers do.
//  * Points that are blends of markers fixed above (middle and ring Meta = Hand3 + 0.33/0.66 ·
//    (Hand1 − Hand3)) cannot take arbitrary values: the simulator's truth hand is projected
//    onto the mapping (make_consistent) before anything is generated, so the truth it reports
//    and the TRC agree exactly. Palm normal and direction have no markers (mapped as zero).
#include <string>
#include <vector>

#include "core/hand/hand_frame.h"
#include "core/io/trc.h"
#include "core/io/vicon_mapping.h"

namespace lmc::devices {

class TruthMarkerMap {
 public:
  // Throws lmc::Error when the mapping cannot be inverted this way.
  explicit TruthMarkerMap(ViconMapping mapping);

  const std::vector<std::string>& marker_names() const { return mapping_.markers; }
  const ViconMapping& mapping() const { return mapping_; }
  // Marker positions for a (consistent) truth frame.
  std::vector<Vec3> markers(const HandFrame& truth) const;
  // Rewrites every mapped point as the mapping's weighted sum of markers(truth).
  void make_consistent(HandFrame& truth) const;

  static constexpr double kStyloidHalfWidthMm = 25.0;

 private:
  enum class Source { kPoint, kPairPlus, kPairMinus };
  struct MarkerSource {
    Source source = Source::kPoint;
    int point = -1;
  };
  ViconMapping mapping_;
  std::vector<MarkerSource> sources_;
};

// A TRC (mm, `rate_hz`) of `frames` (world coordinates, one per 1/rate_hz s).
TrcData truth_trc(const std::vector<HandFrame>& frames, double rate_hz, const TruthMarkerMap& map);

}  // namespace lmc::devices
