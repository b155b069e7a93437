#include "core/calibration/calibration_samples.h"

#include <cmath>

namespace lmc {

const char* point_group_name(int group) {
  switch (group) {
    case kGroupPalm:
      return "palm";
    case kGroupWrist:
      return "wrist";
    case kGroupMetacarpalBases:
      return "metacarpal bases";
    default:
      return "knuckles";
  }
}

const std::array<CalibrationPoint, kNumCalibrationPoints>& calibration_points() {
  static const std::array<CalibrationPoint, kNumCalibrationPoints> points = [] {
    std::array<CalibrationPoint, kNumCalibrationPoints> p{};
    p[0] = {kPalm, kGroupPalm, -1};
    p[1] = {kWrist, kGroupWrist, -1};
    int k = 2;
    for (int digit = 1; digit < kNumDigits; ++digit) {
      p[static_cast<size_t>(k++)] = {digit_point(digit, 0), kGroupMetacarpalBases, digit};
      p[static_cast<size_t>(k++)] = {digit_point(digit, 1), kGroupKnuckles, digit};
    }
    return p;
  }();
  return points;
}

std::uint8_t unclamped_axes(const Vec3& p, std::uint8_t clamping_axes, const SampleRules& rules) {
  std::uint8_t axes = 0;
  for (int k = 0; k < 3; ++k) {
    const double a = std::abs(p[k]);
    const bool in_band =
        a >= rules.axis_cut_mm - rules.axis_cut_below_mm && a <= rules.axis_cut_mm + rules.axis_cut_above_mm;
    if (((clamping_axes >> k) & 1U) == 0 || !in_band) axes |= static_cast<std::uint8_t>(1U << k);
  }
  return axes;
}

DeviceSamples gather_samples(const HandTrack& track, const std::vector<FingerLabels>& labels,
                             const SampleRules& rules) {
  DeviceSamples s;
  const auto& points = calibration_points();
  const int frames = std::min(track.frame_count, static_cast<int>(labels.size()));
  for (int f = 0; f < frames; ++f) {
    if (!track.has_hand(f)) continue;
    const FingerLabels& l = labels[static_cast<size_t>(f)];
    bool any_visible = false;
    for (const auto v : l) any_visible = any_visible || v == 1;
    if (!any_visible) continue;
    for (int k = 0; k < kNumCalibrationPoints; ++k) {
      const CalibrationPoint& cp = points[static_cast<size_t>(k)];
      if (cp.digit >= 0 && l[static_cast<size_t>(cp.digit)] != 1) continue;
      const Vec3& p = track.at(f, cp.point);
      if (!is_finite(p)) continue;
      s.frame.push_back(f);
      s.point.push_back(k);
      s.p.push_back(p);
    }
  }
  // Which axes this controller clamps: those with a pile-up of coordinates exactly on the cut.
  std::array<int, 3> on_cut{};
  for (const Vec3& p : s.p)
    for (int k = 0; k < 3; ++k)
      if (std::abs(std::abs(p[k]) - rules.axis_cut_mm) < rules.on_cut_tolerance_mm) ++on_cut[static_cast<size_t>(k)];
  std::uint8_t clamping = 0;
  for (int k = 0; k < 3; ++k)
    if (on_cut[static_cast<size_t>(k)] >= rules.min_on_cut) clamping |= static_cast<std::uint8_t>(1U << k);
  DeviceSamples out;
  for (int i = 0; i < s.size(); ++i) {
    const std::uint8_t axes = unclamped_axes(s.p[static_cast<size_t>(i)], clamping, rules);
    if (axes != kAllAxes) {
      ++out.beyond_cut;
      if (axes == 0) {
        ++out.dropped_beyond_cut;
        continue;
      }
    }
    out.frame.push_back(s.frame[static_cast<size_t>(i)]);
    out.point.push_back(s.point[static_cast<size_t>(i)]);
    out.p.push_back(s.p[static_cast<size_t>(i)]);
    out.axes.push_back(axes);
  }
  return out;
}

}  // namespace lmc
