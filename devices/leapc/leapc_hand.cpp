#include "devices/leapc/leapc_hand.h"

namespace lmc::devices {
namespace {

Vec3 to_vec(const leapc::Vector& v) {
  return {v.x, v.y, v.z};
}

HandType to_hand_type(std::uint32_t t) {
  return t == leapc::kHandLeft ? HandType::kLeft : HandType::kRight;
}

// The study's 28 points + 2 vectors (docs/algorithms/hand-points.md).
void copy_hand(const leapc::Hand& h, HandFrame& f) {
  f.point(kPalm) = to_vec(h.palm.position);
  f.point(kPalmNormal) = to_vec(h.palm.normal);
  f.point(kPalmDirection) = to_vec(h.palm.direction);
  f.point(kElbow) = to_vec(h.arm.prev_joint);
  f.point(kWrist) = to_vec(h.arm.next_joint);
  for (int d = 0; d < kNumDigits; ++d) {
    const leapc::Digit& digit = h.digits[d];
    f.point(digit_point(d, 0)) = to_vec(digit.bones[0].prev_joint);
    for (int b = 0; b < 4; ++b) f.point(digit_point(d, b + 1)) = to_vec(digit.bones[b].next_joint);
  }
}

}  // namespace

SourceFrame leapc_frame(const leapc::TrackingEvent& t, HandType wanted) {
  SourceFrame f;
  // The image frame id, as the study's files hold it: it skips when the service drops images as
  // well as when this client polls too slowly (tracking_frame_id skips only then).
  f.frame.frame_id = t.info.frame_id;
  f.frame.timestamp_us = t.info.timestamp;
  f.frame.frame_rate_hz = t.framerate;
  f.frame.points.fill(Vec3::Zero());
  const leapc::Hand* chosen = nullptr;
  for (std::uint32_t i = 0; i < t.nHands && chosen == nullptr; ++i)
    if (to_hand_type(t.pHands[i].type) == wanted) chosen = &t.pHands[i];
  if (chosen == nullptr && t.nHands == 1) {
    chosen = &t.pHands[0];
    f.other_side_hand = true;
  }
  if (chosen != nullptr) {
    copy_hand(*chosen, f.frame);
    f.frame.hand_present = true;
    f.hand_type = to_hand_type(chosen->type);
    f.confidence = chosen->confidence;
  }
  return f;
}

}  // namespace lmc::devices
