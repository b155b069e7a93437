#pragma once
// One simulated controller's own hand model (study_errors.h): the per-controller draw of the
// configured scales and joint offsets, and the hand that controller reports instead of the truth.
#include <array>
#include <cstdint>

#include "core/hand/hand_frame.h"
#include "devices/sim/study_errors.h"

namespace lmc::devices {

struct ControllerHandModel {
  std::array<std::array<double, 4>, kNumDigits> scale{};                     // per digit, per bone
  std::array<std::array<Vec3, kJointsPerDigit>, kNumDigits> offset_local{};  // (along bone, palm side, lateral), mm
};

// Draws this controller's model from `seed` (its own stream: nothing else in the rig changes).
// With scale_spread = joint_offset_spread_mm = 0 the draw is exactly the configured values.
ControllerHandModel draw_controller_hand_model(const HandModelError& config, std::uint64_t seed);

// Rewrites every digit of `hand` (world frame, palm normal set) as the controller's model of it:
// each digit's chain is rebuilt from its Meta point with every bone scaled, then each joint moves
// by its offset in a frame of its bone (along the bone; towards the palm side of the bone, i.e.
// the palm's lateral axis × the bone, which follows the finger's flexion; lateral). The palm, wrist,
// elbow and vectors stay.
void apply_controller_hand_model(const ControllerHandModel& model, HandFrame& hand);

}  // namespace lmc::devices
