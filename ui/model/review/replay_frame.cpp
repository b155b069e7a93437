#include "ui/model/review/replay_frame.h"

#include <algorithm>
#include <cmath>

namespace lmc::ui {
namespace {

std::array<Vec3, kNumHandPoints> points_at(const HandTrack& track, int f) {
  std::array<Vec3, kNumHandPoints> p{};
  for (int i = 0; i < kNumHandPoints; ++i) p[static_cast<size_t>(i)] = track.at(f, i);
  return p;
}

}  // namespace

std::optional<ReplayFrame> replay_frame(const TrialAnalysis& r, double t_s) {
  const int n = r.fused.frame_count;
  if (n <= 0) return std::nullopt;
  ReplayFrame out;
  const double step_s = r.world.step_us * 1e-6;
  out.frame = std::clamp(static_cast<int>(std::lround(t_s / step_s)), 0, n - 1);
  out.t_s = out.frame * step_s;
  for (size_t d = 0; d < r.world.devices.size(); ++d) {
    const HandTrack& track = r.world.devices[d].track;
    if (out.frame >= track.frame_count || !track.has_hand(out.frame)) continue;
    LiveHand h;
    h.colour = static_cast<int>(d);
    h.slot = "LMC" + std::to_string(r.world.devices[d].device_id);
    h.world = points_at(track, out.frame);
    out.hands.push_back(h);
  }
  if (r.has_vicon && out.frame < r.vicon.frame_count) {
    LiveHand v;
    v.colour = kViconHandColour;
    v.slot = "Vicon";
    v.world = points_at(r.vicon, out.frame);
    out.hands.push_back(v);
  }
  FusedHand fused;
  fused.t_s = out.t_s;
  fused.points = points_at(r.fused, out.frame);
  fused.has_hand = r.fused.has_hand(out.frame);
  // Seen by: the ray-traced labels of this frame, as the live view counts them.
  for (const auto& labels : r.labels) {
    if (out.frame >= static_cast<int>(labels.size())) continue;
    for (int k = 0; k < kNumDigits; ++k) fused.seen_by[static_cast<size_t>(k)] += labels[out.frame][k] == 1 ? 1 : 0;
  }
  out.fused = fused;
  return out;
}

}  // namespace lmc::ui
