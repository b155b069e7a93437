#include "core/hand/pose_set_generator.h"

namespace lmc {

PoseSet generate_pose_set(const HandModel&, const PoseSetSettings&) { return {}; }

}  // namespace lmc
