#pragma once
// The 3D replay of the Review tab: what the live-hands view draws at one time of a
// processed trial — each controller's realigned hand in its slot colour, the Vicon hand (mapped
// markers, light grey) and the fused hand coloured by how many controllers saw each finger at that
// frame — so the picture and the plots' cursor show the same instant.
#include <optional>
#include <vector>

#include "core/processing/online_fusion.h"
#include "core/processing/trial_pipeline.h"
#include "ui/model/devices/live_hands.h"

namespace lmc::ui {

inline constexpr int kViconHandColour = 7;  // device_colour(7): light grey

struct ReplayFrame {
  int frame = 0;
  double t_s = 0;
  std::vector<LiveHand> hands;  // controllers with a hand at this frame, then Vicon when present
  std::optional<FusedHand> fused;
};

// The frame nearest to `t_s` (clamped to the trial); nothing for a trial without frames.
std::optional<ReplayFrame> replay_frame(const TrialAnalysis& result, double t_s);

}  // namespace lmc::ui
