#pragma once
// Settings of the simulated rig. Every behaviour can be switched in JSON
// (sim_config_from_json); the defaults imitate the study's four-controller rig: each device
// 11–34 Hz (four devices sharing the USB bus, paper "Data Collection"), ≈1 mm noise (or the
// controller model's own where the catalogue gives one: noise_sigma_mm below), no hand when the
// approach / field-of-view test fails, hidden fingers replaced by a lagging, biased internal-model
// guess, coordinates cut at ±250 mm, an elbow 10–20 mm off (paper, Discussion) and per-device
// calibration error equal to the layout's measured offsets.
//
// Calibration convention: a simulated device reports p_d = Rᵀ·(p_true − t − c) where R, t are the
// layout pose and c is the device's calibration error. Realigning with pose AND the layout's
// offset (p = R·p_d + t + offset, docs/algorithms/frames.md) gives the truth exactly when
// offset = c, i.e. the layout offset IS the calibration error processing must undo. With
// calibration "layout" (default) c = the layout's offset; "none" sets c = 0; "custom" takes
// `calibration_offsets_mm` per slot.
//
// Rotation error: the device also stands turned by E about its own origin, so it
// reports p_d = (E·R)ᵀ·(p_true − t − c) and only a transform with rotation E·R reproduces the
// truth. E comes from `calibration_rotations_deg` per slot (rx, ry, rz as a layout pose's angles,
// E = Rz·Ry·Rx) in any mode; none by default. On top of either, `calibration_random_translation_mm`
// and `calibration_random_rotation_deg` (0 by default) add a seeded random error per device:
// a uniform direction with a length uniform in [0, N] mm, a uniform axis with an angle uniform in
// [0, M]°. SimRig::true_device_to_world() gives the resulting transform.
#include <cstdint>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/hand/reference_poses.h"
#include "core/layout/sensor_catalogue.h"
#include "devices/sim/study_errors.h"

namespace lmc::devices {

struct SimUnplug {
  std::string slot;
  double at_s = 0;
  double duration_s = 1;  // < 0: never comes back
};

struct SimConfig {
  std::uint64_t seed = 1;
  // Seed of the random calibration error alone (default: `seed`). A session gives every trial its
  // own `seed` but one calibration seed, so its controllers stand in the same wrong places in every
  // trial, as real ones do between calibrations.
  std::optional<std::uint64_t> calibration_seed;
  // Motion: one of the study's motions, or a pose-set file played in a loop.
  HandOrientation orientation = HandOrientation::kHorizontal;
  HandMotion motion = HandMotion::kOpen;
  std::string pose_set_path;       // when set, replaces orientation/motion
  double pose_set_rate_hz = 10.0;  // pose-set frames per second (linearly interpolated)
  double motion_period_s = 3.0;    // open → end of range → open
  double sway_mm = 2.0;            // slow physiological sway of the whole hand
  double hand_length_mm = 190.0;
  double hand_breadth_mm = 85.0;

  // Rates: each device draws a rate in [min, max] and wanders inside it.
  double rate_min_hz = 11.0;
  double rate_max_hz = 34.0;
  double rate_wander = 0.08;  // per-frame random-walk step as a fraction of the range
  double latency_min_ms = 1.0, latency_max_ms = 4.0;
  std::int64_t device_clock_start_us = 2'998'000'000;  // the Leap clock's epoch is arbitrary

  bool noise = true;
  // Gaussian noise σ per axis (mm) on every reported point. Unset (the default, JSON without the
  // key or null): each controller uses its slot's model's catalogue figure (position_noise_sd_mm:
  // lmc 1.75, lmc2 0.6), or kDefaultPositionNoiseSdMm where the model has none, so a rig of the
  // study's model is simulated as it always was. Set: this σ for every controller, whatever its
  // model; a lab that measured its own rig's noise sets it. The stand-in model does not change it.
  std::optional<double> noise_sigma_mm;
  bool fov_test = true;   // no hand when the approach / range / pyramid test fails
  double range_mm = 0;    // 0: the layout's sensor range
  bool occlusion = true;  // hidden fingers come from the internal model
  double phalanx_radius_mm = 10.0;
  double internal_model_bias = 0.35;  // blend of the guess towards the open-hand finger
  bool axis_cut = true;
  double axis_cut_mm = 250.0;
  bool elbow_error = true;
  double elbow_error_min_mm = 10.0, elbow_error_max_mm = 20.0;
  enum class Calibration { kLayout, kNone, kCustom };
  Calibration calibration = Calibration::kLayout;
  std::map<std::string, Eigen::Vector3d> calibration_offsets_mm;     // kCustom, by slot
  std::map<std::string, Eigen::Vector3d> calibration_rotations_deg;  // any mode, by slot: (rx, ry, rz)
  double calibration_random_translation_mm = 0;  // seeded random error per device, up to this length
  double calibration_random_rotation_deg = 0;    // and up to this angle
  // The controllers' own hand models (study_errors.h). `study_errors` records that the
  // fitted preset was asked for (JSON `"study_errors": true`); the values live in the fields.
  bool study_errors = false;
  HandModelError hand_model_error;
  std::vector<SimUnplug> unplugs;
  std::string serial_prefix = "SIM";
  // The catalogue model every simulated controller reports itself as ("lmc2"), whatever its slot
  // is laid out as; empty: each reports its slot's model (the study's model reports as the original
  // controller). Its range and field of view stay the slot's: the rig tests what a lab would see.
  std::string stand_in_model;

  double truth_rate_hz = 100.0;  // ground-truth TRC rate
};

// The noise σ (mm per axis) of a simulated controller of catalogue model `model` (nullptr: none):
// the configured noise_sigma_mm, else the model's position_noise_sd_mm, else kDefaultPositionNoiseSdMm.
double sim_noise_sigma_mm(const SimConfig& config, const SensorSpec* model);

SimConfig sim_config_from_json(const nlohmann::json& j, const std::string& source);
nlohmann::json sim_config_to_json(const SimConfig& c);
SimConfig load_sim_config(const std::string& path);

// "static", "index", "thumb", "wrist" (= wrist flexion), "wrist-extension", optionally prefixed
// by "horizontal/" or "vertical/" (or "-"); anything else naming an existing file is a pose set.
// Throws lmc::Error for an unknown motion.
void apply_motion_spec(SimConfig& config, const std::string& spec);
std::string motion_spec(const SimConfig& config);

}  // namespace lmc::devices
