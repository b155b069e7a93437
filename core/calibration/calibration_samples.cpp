#include "core/calibration/calibration_samples.h"

namespace lmc::calibration {

const char* point_group_name(int group) {
  switch (group) {
    case kGroupPalm: return "palm";
    case kGroupWrist: return "wrist";
    case kGroupMetacarpalBases: return "metacarpal bases";
    default: return "knuckles";
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

DeviceSamples gather_samples(const HandTrack& track, const std::vector<FingerLabels>& labels) {
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
  return s;
}

}  // namespace lmc::calibration
