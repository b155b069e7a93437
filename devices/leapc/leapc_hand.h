#pragma once
// A LeapC tracking event as the frame the hub takes: the study's 28 points and 2 vectors of the
// hand of the wanted side, the service's image frame id and its timestamp.
#include "core/hand/hand_frame.h"
#include "devices/frame_source.h"
#include "devices/leapc/leapc_abi.h"

namespace lmc::devices {

// The hand of `wanted` side; when the only hand in view is classified as the other side it is the
// subject's hand misclassified (the study's subjects held one hand in the rig): kept, and marked
// (SourceFrame::other_side_hand). Serial and host time are the caller's to fill.
SourceFrame leapc_frame(const leapc::TrackingEvent& t, HandType wanted);

}  // namespace lmc::devices
