#pragma once
// The palm's normal and direction estimated from the hand's points, for hands that carry none (Vicon
// markers mapped to the 30 points leave both zero, docs/algorithms/vicon.md) and for comparing pose
// sets on one definition whatever produced them (a controller's reported vectors and a marker set's
// would otherwise differ by construction).
//   direction: wrist → the middle finger's metacarpal base (Meta), unit length;
//   normal:    (index Meta − pinky Meta) × direction, made perpendicular to the direction, unit
//              length. For a right hand this points out of the palm (down for a palm-down hand), as
//              a controller reports it; for a left hand it points out of the back.
// Both are NaN when a point they need is not finite or the hand is degenerate (coincident points).
#include "core/hand/hand_frame.h"

namespace lmc {

struct PalmAxes {
  Vec3 normal, direction;
};

PalmAxes estimate_palm_axes(const HandFrame& frame);

}  // namespace lmc
