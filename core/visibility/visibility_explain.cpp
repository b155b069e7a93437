#include "core/visibility/visibility_explain.h"

#include "core/visibility/visibility_tests.h"

namespace lmc {

VisibilityExplanation explain_visibility(const PreparedFrame&, const DeviceView&, const VisibilityLimits&) {
  return {};
}

std::string_view hidden_reason_name(HiddenReason r) {
  switch (r) {
    case HiddenReason::kVisible: return "visible";
    case HiddenReason::kNoHand: return "no hand";
    case HiddenReason::kWrongApproach: return "wrong approach";
    case HiddenReason::kOutOfRange: return "out of range";
    case HiddenReason::kOutOfView: return "out of view";
    case HiddenReason::kBehindPalm: return "behind the palm";
    case HiddenReason::kBehindFinger: return "behind finger";
  }
  return "?";
}

std::string describe(const FingerVerdict& v) { return std::string(hidden_reason_name(v.reason)); }

}  // namespace lmc
