#pragma once
// Controllers that cannot see the hand at all: placed or turned so that the hand the study asks for
// is beyond their range, outside their field of view or comes at them from behind. A lab that
// streams such a layout sees "no hand" from that controller in every frame, which looks like a
// broken controller; the workbench says which one and why instead.
#include <string>
#include <vector>

#include "core/layout/layout.h"
#include "core/visibility/visibility_explain.h"

namespace lmc {

struct BlindController {
  int device = -1;  // index into layout.devices
  std::string slot;
  // What hides the hand from it in most of the poses (the whole-hand tests come first: a wrong
  // approach, out of range, out of view; then the palm or a finger in the way).
  HiddenReason reason = HiddenReason::kOutOfView;
};

// The controllers of `layout` (with its sensor model) that see no finger in any of the study's ten
// reference poses (reference_poses.h, the average hand of hand_model.h): the hand region above the
// table centre where every trial happens. In layout order; empty when every controller sees some
// finger in some pose.
std::vector<BlindController> blind_controllers(const Layout& layout);

}  // namespace lmc
