#pragma once
// Per-subject finger-length correction: optional, off by default, for the
// default fusion only.
//
// Why: every controller reports the fingers shorter than Vicon's skin markers (the shared real
// trial: 11–32 %), and no fusion can undo a bias all controllers share. For one subject the bias is
// largely a fixed scale per finger (each controller's hand model), so it can be measured once and
// divided out: one factor per finger, fitted either
//  * on one static trial with Vicon: Vicon's finger length / the fused finger length, both as means
//    over the frames where both have the finger; or
//  * from the subject's hand length and breadth typed in: the anthropometric finger length the
//    simulator's hand model uses (HandModel, Buchholz et al. 1992) / the fused finger length over
//    one trial of that subject (no Vicon needed).
// One factor per finger, not per bone: one static trial has little to say about single bones, and
// the controllers' error is a scale of the whole digit (devices/README.md, segment_scale).
//
// Applying it multiplies each bone of a fused finger's length (thumb Inter→Dist→End, fingers
// Proxi→Inter→Dist→End, the segments of measures.h) by the finger's factor, rebuilding the finger
// outward from its first joint: every bone keeps its direction, so every joint angle is unchanged.
// It changes what a fusion reports, so it is never applied to the reference method (the study's
// algorithm, byte for byte) and never fitted and scored on the same trial in a figure.
#include <array>
#include <string>
#include <vector>

#include "core/hand/hand_track.h"
#include "core/processing/measures.h"

namespace lmc {

enum class LengthSource { kVicon, kHandDimensions };
const char* length_source_name(LengthSource s);  // "vicon", "hand_dimensions"

struct LengthCorrection {
  std::string subject;
  LengthSource source = LengthSource::kVicon;
  std::string fit_trial;                           // the trial the factors were fitted on
  std::string fit_lmc_file;                        // its LMC file
  std::string fit_vicon_file;                      // its Vicon file (source vicon)
  double hand_length_mm = 0, hand_breadth_mm = 0;  // source hand_dimensions
  int fit_frames = 0;                           // fewest frames any finger was fitted on (finite in fused and target)
  std::array<double, kNumFingers> fused_mm{};   // fused finger length, mean over the fit frames
  std::array<double, kNumFingers> target_mm{};  // what it should be (Vicon mean / anthropometry)
  std::array<double, kNumFingers> factor{};     // target / fused
};

// Factors outside this range mean the wrong subject, Vicon file or mapping, not a controller's
// hand model (the real trial needs 1.15–1.31): fitting and reading refuse them.
inline constexpr double kMinLengthFactor = 0.5;
inline constexpr double kMaxLengthFactor = 2.0;

// The finger lengths (measures.h: thumb proximal + distal phalanx, fingers proximal + middle +
// distal) of the anthropometric hand of this length and breadth (HandModel). Throws lmc::Error
// for a non-finite, non-positive or implausible size.
std::array<double, kNumFingers> expected_finger_lengths_mm(double hand_length_mm, double hand_breadth_mm);

// Fit on one trial's per-frame measures of the default fusion (and of Vicon, same frames).
// `where` names the trial (and Vicon file) in messages. Throws lmc::Error when a finger has no
// frame with both lengths (a Vicon marker of that finger missing throughout), a fused or Vicon
// bone is zero long over the trial, or a factor falls outside [kMinLengthFactor, kMaxLengthFactor].
LengthCorrection fit_length_correction_to_vicon(const std::vector<FrameMeasures>& fused,
                                                const std::vector<FrameMeasures>& vicon, const std::string& where);
LengthCorrection fit_length_correction_to_hand(const std::vector<FrameMeasures>& fused, double hand_length_mm,
                                               double hand_breadth_mm, const std::string& where);

// Throws lmc::Error (naming `where`) unless every factor is finite and within the range above.
void check_length_factors(const std::array<double, kNumFingers>& factor, const std::string& where);

// Scales each finger's bones by its factor in place (see the file comment). NaN stays NaN.
void apply_length_correction(HandTrack& track, const LengthCorrection& c);

}  // namespace lmc
