#include "core/hand/reference_poses.h"

namespace lmc {

std::string_view orientation_name(HandOrientation o) { return o == HandOrientation::kHorizontal ? "horizontal" : "vertical"; }
std::string_view motion_name(HandMotion) { return "open"; }
std::optional<HandOrientation> orientation_from_name(std::string_view) { return std::nullopt; }
std::optional<HandMotion> motion_from_name(std::string_view) { return std::nullopt; }
std::string pose_label_name(HandOrientation o, HandMotion m) {
  return std::string(orientation_name(o)) + "/" + std::string(motion_name(m));
}
HandJointAngles motion_angles(HandMotion, double) { return {}; }
const MotionRanges& motion_ranges() {
  static const MotionRanges r;
  return r;
}
HandPlacement reference_placement(const HandModel&, HandOrientation) { return {}; }
HandFrame reference_pose(const HandModel& model, HandOrientation, HandMotion) { return model.pose({}); }

}  // namespace lmc
