#include "core/visibility/blind_controllers.h"

#include <algorithm>
#include <array>
#include <iterator>

#include "core/hand/reference_poses.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

std::vector<BlindController> blind_controllers(const Layout& layout) {
  const HandModel model;
  std::vector<PreparedFrame> poses;
  for (int o = 0; o < kNumHandOrientations; ++o) {
    for (int m = 0; m < kNumHandMotions; ++m) {
      poses.push_back(
          prepare_frame(reference_pose(model, static_cast<HandOrientation>(o), static_cast<HandMotion>(m))));
    }
  }
  const std::vector<VisibilityLimits> device_lims = device_limits(layout);
  std::vector<BlindController> out;
  for (int d = 0; d < layout.device_count(); ++d) {
    const VisibilityLimits& limits = device_lims[static_cast<size_t>(d)];
    const DeviceView view = DeviceView::from_device(layout.devices[static_cast<size_t>(d)]);
    // How often each reason hides a finger; a controller that sees any finger once is not blind.
    std::array<int, static_cast<size_t>(HiddenReason::kBehindFinger) + 1> reasons{};
    bool sees = false;
    for (const PreparedFrame& pose : poses) {
      const VisibilityExplanation why = explain_visibility(pose, view, limits);
      if (why.bits != 0) {
        sees = true;
        break;
      }
      for (const FingerVerdict& v : why.fingers) ++reasons[static_cast<size_t>(v.reason)];
    }
    if (sees) continue;
    // Ties go to the earlier test, the one the explanation reports first.
    const auto most = std::max_element(reasons.begin(), reasons.end());
    out.push_back({d, layout.devices[static_cast<size_t>(d)].slot,
                   static_cast<HiddenReason>(std::distance(reasons.begin(), most))});
  }
  return out;
}

}  // namespace lmc
