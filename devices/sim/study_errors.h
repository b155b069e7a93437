#pragma once
// The simulator's "study errors" settings: what a real controller reports
// differently from Vicon's skin markers even where it sees the hand perfectly.
//
// Each controller fits its own skeletal hand model, so (a) its bones are shorter than the
// distances between Vicon's skin markers (the study: every controller's fingers 11–32 % shorter),
// and (b) its joint centres sit inside the finger, below the dorsal skin markers. A simulated
// controller reports its hand model instead of the truth: every bone of a digit scaled by
// `segment_scale` (times a per-controller factor 1 + N(0, scale_spread), one per digit), joints
// shifted towards the palm side of their bones by `joint_offset_mm` (per joint: Meta, Proxi, Inter,
// Dist, End) plus a per-controller Gaussian offset of SD `joint_offset_spread_mm`. The per-controller
// draws come from the calibration seed, so a controller keeps its model through a session.
//
// `study_errors: true` in the simulator JSON switches this on with the values fitted to the
// shared real trial and the paper (study_errors_preset(); devices/README.md, "Simulator: study
// errors"), and sets the residual device-to-world misalignment with the existing
// calibration_random_* settings. Every value can still be overridden key by key. Off by default:
// the default simulator's trials do not depend on this model.
#include <array>
#include <nlohmann/json_fwd.hpp>

#include "core/io/json_checked.h"

namespace lmc::devices {

struct HandModelError {
  bool enabled = false;
  // Per digit (thumb, index, middle, ring, pinky), per bone (Meta→Proxi, Proxi→Inter,
  // Inter→Dist, Dist→End): the controller's bone length over the truth's.
  std::array<std::array<double, 4>, 5> segment_scale{
      {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}}};
  double scale_spread = 0;                  // SD of the per-controller, per-digit factor on segment_scale
  std::array<double, 5> joint_offset_mm{};  // towards the palm side of the bone, per joint
  double joint_offset_spread_mm = 0;        // SD per axis, per controller, digit and joint
};

// The fitted values (and the misalignment the preset adds, below).
HandModelError study_errors_hand_model();
inline constexpr double kStudyCalibrationTranslationMm = 8.0;
inline constexpr double kStudyCalibrationRotationDeg = 2.0;

// Reads `hand_model_error` over `base` (keys left out keep base's values); throws lmc::Error
// naming the path on a wrong key or value.
HandModelError hand_model_error_from_json(const JsonReader& r, HandModelError base);
nlohmann::json hand_model_error_to_json(const HandModelError& e);

}  // namespace lmc::devices
