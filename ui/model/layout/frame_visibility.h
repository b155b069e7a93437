#pragma once
// Visibility of the hand in the frame on screen, from the engine's explaining path
// (core/visibility/visibility_explain.h): per device the five verdicts, per finger how many
// devices see it (the scene's finger colours), and for one chosen device a line to every finger
// marker with its verdict (the scene's rays and their tooltips). A handful of explain calls per
// frame: cheap enough for the UI thread.
#include <array>
#include <string>
#include <vector>

#include "core/layout/layout.h"
#include "core/visibility/visibility_explain.h"
#include "ui/scene/finger_ray.h"

namespace lmc::ui {

struct FrameVisibility {
  std::vector<VisibilityExplanation> per_device;  // layout order
  std::array<int, kNumDigits> seen_count{-1, -1, -1, -1, -1};
  std::vector<FingerRay> rays;  // from `ray_device` to the 20 finger markers
};

// `frame` is the prepared form of the hand frame on screen; `ray_device` < 0 for no rays.
FrameVisibility explain_frame(const Layout& layout, const PreparedFrame& frame, int ray_device);

// Tooltip text for a ray verdict: "clear", "out of view", "behind the palm", "behind the middle finger".
std::string ray_reason_text(const FingerVerdict& verdict);

}  // namespace lmc::ui
