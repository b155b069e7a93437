#pragma once
// The pictogram of what the subject is asked to do in a trial: the hand model's start
// and end pose of the trial's motion — the same motion the simulated rig plays for that trial type,
// named by the protocol ("vertical/index") and read by the simulator's own parser — and the pose
// in between at a moment of a slow back-and-forth animation. Poses come from core
// (motion_pose); the Record tab and the subject screen only draw them.
#include <optional>
#include <string>

#include "core/hand/hand_frame.h"
#include "core/hand/reference_poses.h"

namespace lmc::ui {

struct MotionPictogram {
  HandOrientation orientation = HandOrientation::kHorizontal;
  HandMotion motion = HandMotion::kOpen;
  HandFrame start, end, now;  // world frame, mm
  double progress = 0;        // of `now`, 0 = start, 1 = end
};

// One animation cycle: hold the start pose, move to the end pose, hold it, move back.
inline constexpr double kPictogramPeriodS = 3.0;
// Where the animation is `t_s` seconds in: 0 (start) … 1 (end), smooth at both ends.
double pictogram_progress(double t_s, double period_s = kPictogramPeriodS);

// `sim_motion` is a trial's "<pose key>/<motion>" (PlannedTrial::sim_motion); the hand is the
// subject's when its sizes are known (0: the model's average adult hand). Empty when the motion is
// not one of the study's (a pose-set file plays instead: nothing to draw).
std::optional<MotionPictogram> motion_pictogram(const std::string& sim_motion, double t_s, double hand_length_mm = 0,
                                                double hand_breadth_mm = 0);

}  // namespace lmc::ui
