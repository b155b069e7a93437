#pragma once
// The explaining face of the visibility test: the same elementary tests as the kernel
// (visibility_tests.h), run without shortcuts across fingers, recording *why* each finger is
// hidden. For the workbench's inspector and for tests; the bits always equal the kernel's.
#include <array>
#include <string>

#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

enum class HiddenReason : int {
  kVisible = 0,
  kNoHand,         // the frame has no (valid) hand
  kWrongApproach,  // a·f < 0: the hand does not enter from the user's side (all fingers)
  kOutOfRange,     // marker farther than the range (all fingers)
  kOutOfView,      // marker outside the viewing pyramid (all fingers)
  kBehindPalm,     // the ray to one of the finger's markers crosses the palm hull
  kBehindFinger,   // the ray to one of the finger's markers passes through another finger's phalanx
};

struct FingerVerdict {
  HiddenReason reason = HiddenReason::kVisible;
  int marker = -1;             // ray marker index s_k that failed (−1 for visible / approach / no hand)
  int occluding_finger = -1;   // kBehindFinger: the finger g whose phalanx blocks the ray
  int occluding_phalanx = -1;  // kBehindFinger: phalanx index 0…14 (3·g + segment)

  bool visible() const { return reason == HiddenReason::kVisible; }
  bool operator==(const FingerVerdict&) const = default;
};

struct VisibilityExplanation {
  FingerBits bits = 0;
  std::array<FingerVerdict, kNumDigits> fingers{};
  double approach_dot = 0;  // a·f
};

// For a hidden finger the reason is the first failing test in the order of docs/algorithms/visibility.md (approach,
// then range/pyramid over s1…s21 in index order, then for each of the finger's markers in order: palm, then other
// fingers' phalanges in index order).
VisibilityExplanation explain_visibility(const PreparedFrame& frame, const DeviceView& device,
                                         const VisibilityLimits& limits);

// "wrong approach", "marker s7 (Finger2_Dist) out of range", "marker s7 (Finger2_Dist) behind
// finger middle", …
std::string describe(const FingerVerdict& verdict);
std::string_view hidden_reason_name(HiddenReason r);

}  // namespace lmc
