#include "core/visibility/visibility_explain.h"

#include "core/visibility/visibility_tests.h"

namespace lmc {

VisibilityExplanation explain_visibility(const PreparedFrame& fr, const DeviceView& d, const VisibilityLimits& lim) {
  VisibilityExplanation ex;
  auto hide_all = [&](HiddenReason reason, int marker) {
    for (auto& v : ex.fingers) v = FingerVerdict{reason, marker, -1, -1};
    ex.bits = 0;
    return ex;
  };
  if (!fr.valid) return hide_all(HiddenReason::kNoHand, -1);
  ex.approach_dot = vis::approach_dot(fr, d);
  if (!vis::approach_ok(fr, d)) return hide_all(HiddenReason::kWrongApproach, -1);
  for (int k = 1; k < kNumRayMarkers; ++k) {
    const auto kk = static_cast<size_t>(k);
    const auto r = vis::marker_in_view(fr.mx[kk], fr.my[kk], fr.mz[kk], d, lim);
    if (r == vis::ViewResult::kOutOfRange) return hide_all(HiddenReason::kOutOfRange, k);
    if (r == vis::ViewResult::kOutOfView) return hide_all(HiddenReason::kOutOfView, k);
  }
  const double plane_num = vis::palm_plane_numerator(fr, d);
  vis::PhalanxBlock pb;
  vis::prepare_phalanges(fr, d, pb);
  ex.bits = kAllFingersVisible;
  for (int f = 0; f < kNumDigits; ++f) {
    FingerVerdict& verdict = ex.fingers[static_cast<size_t>(f)];
    for (int j = 0; j < 4 && verdict.visible(); ++j) {
      const int k = finger_marker(f, j);
      const auto kk = static_cast<size_t>(k);
      const double vx = fr.mx[kk] - d.ox, vy = fr.my[kk] - d.oy, vz = fr.mz[kk] - d.oz;
      if (vis::palm_occludes(fr, d, plane_num, vx, vy, vz)) {
        verdict = {HiddenReason::kBehindPalm, k, -1, -1};
        break;
      }
      const double vv = vx * vx + vy * vy + vz * vz;
      for (int p = 0; p < kNumPhalanges; ++p) {
        const int g = p / 3;
        if (g == f) continue;
        if (vis::phalanx_occludes(pb, p, vx, vy, vz, vv, lim.radius_sq)) {
          verdict = {HiddenReason::kBehindFinger, k, g, p};
          break;
        }
      }
    }
    if (!verdict.visible()) ex.bits = static_cast<FingerBits>(ex.bits & ~(1u << f));
  }
  return ex;
}

std::string_view hidden_reason_name(HiddenReason r) {
  switch (r) {
    case HiddenReason::kVisible:
      return "visible";
    case HiddenReason::kNoHand:
      return "no hand";
    case HiddenReason::kWrongApproach:
      return "wrong approach";
    case HiddenReason::kOutOfRange:
      return "out of range";
    case HiddenReason::kOutOfView:
      return "out of view";
    case HiddenReason::kBehindPalm:
      return "behind the palm";
    case HiddenReason::kBehindFinger:
      return "behind finger";
  }
  return "?";
}

std::string describe(const FingerVerdict& v) {
  std::string marker;
  if (v.marker >= 0) {
    marker = "marker s" + std::to_string(v.marker) + " (" +
             std::string(hand_point_name(ray_marker_hand_point(v.marker))) + ") ";
  }
  switch (v.reason) {
    case HiddenReason::kVisible:
      return "visible";
    case HiddenReason::kNoHand:
      return "no hand";
    case HiddenReason::kWrongApproach:
      return "wrong approach (the hand does not enter from the user's side)";
    case HiddenReason::kOutOfRange:
      return marker + "out of range";
    case HiddenReason::kOutOfView:
      return marker + "out of view";
    case HiddenReason::kBehindPalm:
      return marker + "behind the palm";
    case HiddenReason::kBehindFinger:
      return marker + "behind finger " + std::string(digit_name(v.occluding_finger));
  }
  return "?";
}

}  // namespace lmc
