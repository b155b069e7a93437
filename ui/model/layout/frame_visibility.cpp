#include "ui/model/layout/frame_visibility.h"

#include "core/visibility/device_view.h"
#include "core/visibility/visibility_params.h"

namespace lmc::ui {

std::string ray_reason_text(const FingerVerdict& v) {
  switch (v.reason) {
    case HiddenReason::kVisible:
      return "clear";
    case HiddenReason::kNoHand:
      return "no hand in this frame";
    case HiddenReason::kWrongApproach:
      return "hand does not enter from the user's side (wrong approach)";
    case HiddenReason::kOutOfRange:
      return "hand out of range (" + describe(v) + ")";
    case HiddenReason::kOutOfView:
      return "hand out of view (" + describe(v) + ")";
    case HiddenReason::kBehindPalm:
      return "behind the palm";
    case HiddenReason::kBehindFinger:
      return "behind the " + std::string(digit_name(v.occluding_finger)) + (v.occluding_finger == 0 ? "" : " finger");
  }
  return "?";
}

FrameVisibility explain_frame(const Layout& layout, const PreparedFrame& frame, int ray_device) {
  FrameVisibility out;
  out.seen_count = {0, 0, 0, 0, 0};
  out.per_device.reserve(layout.devices.size());
  for (const LayoutDevice& dev : layout.devices) {
    const VisibilityLimits limits = make_limits(VisibilityParams::from_sensor(dev.sensor));
    out.per_device.push_back(explain_visibility(frame, DeviceView::from_device(dev), limits));
    for (int k = 0; k < kNumDigits; ++k)
      out.seen_count[static_cast<size_t>(k)] += (out.per_device.back().bits >> k) & 1;
  }
  if (ray_device < 0 || ray_device >= layout.device_count() || !frame.valid) return out;
  const LayoutDevice& dev = layout.devices[static_cast<size_t>(ray_device)];
  const Eigen::Vector3d origin = dev.to_world(Eigen::Vector3d::Zero());
  const VisibilityExplanation& ex = out.per_device[static_cast<size_t>(ray_device)];
  for (int f = 0; f < kNumDigits; ++f) {
    const FingerVerdict& v = ex.fingers[static_cast<size_t>(f)];
    // The explaining path checks a finger's markers in order and stops at the first that fails:
    // earlier markers of that finger passed; later ones were not tested (the finger is already
    // hidden), and whole-hand reasons (approach, range, view) apply to every marker.
    int failing_j = -1;
    for (int j = 0; j < 4; ++j) {
      if (finger_marker(f, j) == v.marker) failing_j = j;
    }
    const bool whole_hand = v.reason == HiddenReason::kWrongApproach || v.reason == HiddenReason::kOutOfRange ||
                            v.reason == HiddenReason::kOutOfView || v.reason == HiddenReason::kNoHand;
    for (int j = 0; j < 4; ++j) {
      const int s = finger_marker(f, j);
      FingerRay ray;
      ray.from = origin;
      ray.to = Eigen::Vector3d(frame.mx[static_cast<size_t>(s)], frame.my[static_cast<size_t>(s)],
                               frame.mz[static_cast<size_t>(s)]);
      ray.digit = f;
      ray.marker = ray_marker_hand_point(s);
      if (v.visible()) {
        ray.clear = true;
        ray.reason = "clear";
      } else if (whole_hand) {
        ray.clear = false;
        ray.reason = ray_reason_text(v);
      } else if (j < failing_j) {
        ray.clear = true;
        ray.reason = "clear (but the " + std::string(digit_name(f)) + " is hidden at another marker)";
      } else if (j == failing_j) {
        ray.clear = false;
        ray.reason = ray_reason_text(v);
      } else {
        ray.clear = false;
        ray.reason =
            "not tested: the " + std::string(digit_name(f)) + " is already hidden (" + ray_reason_text(v) + ")";
      }
      out.rays.push_back(std::move(ray));
    }
  }
  return out;
}

}  // namespace lmc::ui
