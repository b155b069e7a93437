#include "core/processing/length_correction.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/hand/hand_model.h"

namespace lmc {
namespace {

// Below this a trial-mean bone is "zero long": a controller or Vicon that collapsed the bone, not a
// short finger (the shortest real phalanx is ~15 mm), and no factor can give it a length.
constexpr double kMinCorrectableBoneMm = 1.0;

std::string corrected_finger_words(int f) {
  return std::string(digit_name(f));
}

// Refuses a finger bone whose mean over the frames that have it is below kMinCorrectableBoneMm.
void refuse_zero_length_bones(const std::vector<FrameMeasures>& frames, const char* whose, const std::string& where) {
  for (int f = 0; f < kNumFingers; ++f) {
    for (int s : finger_segments(f)) {
      double sum = 0;
      int n = 0;
      for (const auto& m : frames) {
        const double v = m.segment_mm[static_cast<size_t>(s)];
        if (std::isfinite(v)) {
          sum += v;
          ++n;
        }
      }
      if (n > 0 && sum / n < kMinCorrectableBoneMm) {
        throw Error(where + ": the " + whose + " " + std::string(segment_name(s)) + " bone is " +
                    format_fixed(sum / n, 2) +
                    " mm long on average: a zero-length bone cannot be corrected by a scale");
      }
    }
  }
}

// The fit shared by both sources: per finger, mean fused length and mean target length over the
// frames where both are finite; factor = target / fused.
LengthCorrection fit_length_factors(const std::vector<FrameMeasures>& fused,
                                    const std::function<double(size_t, int)>& target, const char* target_name,
                                    const std::string& where) {
  refuse_zero_length_bones(fused, "fused", where);
  LengthCorrection c;
  c.fit_frames = static_cast<int>(fused.size());
  for (int f = 0; f < kNumFingers; ++f) {
    const auto fi = static_cast<size_t>(f);
    double sum_fused = 0, sum_target = 0;
    int n = 0;
    for (size_t k = 0; k < fused.size(); ++k) {
      const double a = fused[k].finger_mm[fi], b = target(k, f);
      if (!std::isfinite(a) || !std::isfinite(b)) continue;
      sum_fused += a;
      sum_target += b;
      ++n;
    }
    if (n == 0) {
      throw Error(where + ": no frame has the " + corrected_finger_words(f) + " in both the fused hand and " +
                  target_name + " (a marker of that finger missing in every frame, or no hand fused?)");
    }
    c.fit_frames = std::min(c.fit_frames, n);
    c.fused_mm[fi] = sum_fused / n;
    c.target_mm[fi] = sum_target / n;
    c.factor[fi] = c.target_mm[fi] / c.fused_mm[fi];
  }
  check_length_factors(c.factor, where);
  return c;
}

}  // namespace

const char* length_source_name(LengthSource s) {
  return s == LengthSource::kVicon ? "vicon" : "hand_dimensions";
}

std::array<double, kNumFingers> expected_finger_lengths_mm(double hand_length_mm, double hand_breadth_mm) {
  if (!std::isfinite(hand_length_mm) || hand_length_mm <= 0 || !std::isfinite(hand_breadth_mm) ||
      hand_breadth_mm <= 0) {
    throw Error("hand length and breadth must be positive numbers in mm (given " + format_fixed(hand_length_mm, 1) +
                " and " + format_fixed(hand_breadth_mm, 1) + ")");
  }
  // The simulator's hand model is the one place the anthropometry lives (Buchholz et al. 1992 by
  // hand length; the breadth places the knuckles but changes no finger length).
  const HandGeometry g = HandModel(hand_length_mm, hand_breadth_mm).geometry();
  std::array<double, kNumFingers> len{};
  len[0] = g.phalanx_mm[0][0] + g.phalanx_mm[0][1];
  for (size_t f = 1; f < kNumFingers; ++f) len[f] = g.phalanx_mm[f][0] + g.phalanx_mm[f][1] + g.phalanx_mm[f][2];
  return len;
}

LengthCorrection fit_length_correction_to_vicon(const std::vector<FrameMeasures>& fused,
                                                const std::vector<FrameMeasures>& vicon, const std::string& where) {
  refuse_zero_length_bones(vicon, "Vicon", where);
  const auto target = [&](size_t k, int f) {
    return k < vicon.size() ? vicon[k].finger_mm[static_cast<size_t>(f)] : std::nan("");
  };
  LengthCorrection c = fit_length_factors(fused, target, "Vicon", where);
  c.source = LengthSource::kVicon;
  return c;
}

LengthCorrection fit_length_correction_to_hand(const std::vector<FrameMeasures>& fused, double hand_length_mm,
                                               double hand_breadth_mm, const std::string& where) {
  const auto expected = expected_finger_lengths_mm(hand_length_mm, hand_breadth_mm);
  const auto target = [&](size_t, int f) { return expected[static_cast<size_t>(f)]; };
  LengthCorrection c = fit_length_factors(fused, target, "the hand's dimensions", where);
  c.source = LengthSource::kHandDimensions;
  c.hand_length_mm = hand_length_mm;
  c.hand_breadth_mm = hand_breadth_mm;
  return c;
}

void check_length_factors(const std::array<double, kNumFingers>& factor, const std::string& where) {
  for (int f = 0; f < kNumFingers; ++f) {
    const double k = factor[static_cast<size_t>(f)];
    if (!std::isfinite(k) || k < kMinLengthFactor || k > kMaxLengthFactor) {
      throw Error(where + ": the " + corrected_finger_words(f) + "'s length factor is " +
                  (std::isfinite(k) ? format_fixed(k, 3) : "not a number") + ", outside " +
                  format_fixed(kMinLengthFactor, 1) + "–" + format_fixed(kMaxLengthFactor, 1) +
                  " (controllers are 10–30 % short): wrong subject, Vicon file or mapping?");
    }
  }
}

void apply_length_correction(HandTrack& track, const LengthCorrection& c) {
  for (int f = 0; f < kNumFingers; ++f) {
    const double k = c.factor[static_cast<size_t>(f)];
    const std::span<const int> segs = finger_segments(f);
    for (int fr = 0; fr < track.frame_count; ++fr) {
      // The finger's segments form one chain (each starts where the previous ends): rebuild it
      // from its first joint, each bone along its own direction, k times as long.
      Vec3 old_from = track.at(fr, segment_points(segs.front())[0]);
      Vec3 new_from = old_from;
      for (int s : segs) {
        const int to = segment_points(s)[1];
        const Vec3 old_to = track.at(fr, to);
        const Vec3 new_to = new_from + k * (old_to - old_from);
        track.at(fr, to) = new_to;
        old_from = old_to;
        new_from = new_to;
      }
    }
  }
}

}  // namespace lmc
