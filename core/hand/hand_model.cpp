#include "core/hand/hand_model.h"

namespace lmc {

double joint_param(const HandJointAngles&, int) { return 0.0; }
void set_joint_param(HandJointAngles&, int, double) {}
const char* joint_param_name(int) { return ""; }

HandModel::HandModel(double hand_length_mm, double hand_breadth_mm) {
  geometry_.hand_length_mm = hand_length_mm;
  geometry_.hand_breadth_mm = hand_breadth_mm;
}

HandModel::HandModel(const HandFrame&) {}

HandFrame HandModel::pose(const HandJointAngles&, const HandPlacement&) const {
  HandFrame f;
  f.hand_present = true;
  return f;
}

}  // namespace lmc
