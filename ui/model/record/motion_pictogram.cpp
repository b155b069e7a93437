#include "ui/model/record/motion_pictogram.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "devices/sim/sim_config.h"

namespace lmc::ui {

double pictogram_progress(double t_s, double period_s) {
  if (!(period_s > 0) || !std::isfinite(t_s)) return 0.0;
  // Quarters: hold at the start, ease to the end, hold, ease back. Holding lets the eye read
  // each pose before it moves.
  const double phase = std::fmod(std::fmod(t_s, period_s) + period_s, period_s) / period_s;
  const auto ease = [](double u) { return 0.5 - 0.5 * std::cos(std::numbers::pi * std::clamp(u, 0.0, 1.0)); };
  if (phase < 0.25) return 0.0;
  if (phase < 0.5) return ease((phase - 0.25) * 4.0);
  if (phase < 0.75) return 1.0;
  return 1.0 - ease((phase - 0.75) * 4.0);
}

std::optional<MotionPictogram> motion_pictogram(const std::string& sim_motion, double t_s, double hand_length_mm,
                                                double hand_breadth_mm) {
  devices::SimConfig config;
  try {
    devices::apply_motion_spec(config, sim_motion);  // the simulator's reading of the protocol
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (!config.pose_set_path.empty()) return std::nullopt;
  HandModel model;  // the average adult hand
  if (hand_length_mm > 0 && hand_breadth_mm > 0) {
    try {
      model = HandModel(hand_length_mm, hand_breadth_mm);
    } catch (const std::exception&) {
      // A size the manifest allows but the model cannot build: the picture keeps the average hand.
    }
  }
  MotionPictogram p;
  p.orientation = config.orientation;
  p.motion = config.motion;
  p.progress = p.motion == HandMotion::kOpen ? 0.0 : pictogram_progress(t_s);
  p.start = motion_pose(model, p.orientation, p.motion, 0.0);
  p.end = motion_pose(model, p.orientation, p.motion, 1.0);
  p.now = motion_pose(model, p.orientation, p.motion, p.progress);
  return p;
}

}  // namespace lmc::ui
