#pragma once
// Which pose parameters of one controller are locked, in DevicePose order {x, y, z, rx, ry, rz};
// true = the optimiser and the scene's handles leave that parameter alone. Part of the layout
// document (ui/model/layout/layout_document.h); kept on this floor because the handles read it.
#include <array>

#include "core/layout/device_pose.h"

namespace lmc::ui {

struct DeviceLocks {
  std::array<bool, kNumPoseParams> locked{false, true, false, false, false, true};
  bool operator==(const DeviceLocks&) const = default;
};

}  // namespace lmc::ui
