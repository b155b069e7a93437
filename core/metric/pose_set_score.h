#pragma once
// One layout's headline figures on one pose set — M, how often every finger is seen by two or
// more controllers, how often each finger is seen at all, how often each controller sees some
// finger — so a layout report (and the Layout tab's optimiser result) can put a recorded set and
// the Monte Carlo set side by side: a layout designed on one subject's hands may look better on
// them and worse on the invented ones, and both numbers are needed to see it.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/hand/pose_set.h"
#include "core/layout/layout.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc {

struct PoseSetScore {
  std::string label;        // a short name for tables: "recorded", "Monte Carlo"
  std::string description;  // PoseSet::description
  int frames = 0;
  double metric = 0.0;                           // M (docs/algorithms/metric.md), lower is better
  double redundant_share = 0.0;                  // frames with every finger seen by ≥ 2 controllers
  std::array<double, kNumDigits> finger_seen{};  // frames in which some controller sees the finger
  std::vector<double> controller_seeing;         // per controller: frames in which it sees some finger
};

PoseSetScore pose_set_score(const VisibilityTable& table, std::string label, std::string description);
// Runs the kernel on `prepared` (poses' frames, prepare_frames) first.
PoseSetScore pose_set_score(const Layout& layout, const PoseSet& poses, std::span<const PreparedFrame> prepared,
                            std::string label, double phalanx_radius_mm = 10.0);

}  // namespace lmc
