#include "devices/sim/sim_config.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/delimited_text.h"
#include "core/io/json_checked.h"
#include "core/io/sensor_catalogue_json.h"
#include "core/layout/sensor_catalogue.h"

namespace lmc::devices {
namespace {

const char* calibration_name(SimConfig::Calibration c) {
  switch (c) {
    case SimConfig::Calibration::kLayout:
      return "layout";
    case SimConfig::Calibration::kNone:
      return "none";
    case SimConfig::Calibration::kCustom:
      return "custom";
  }
  return "layout";
}

}  // namespace

double sim_noise_sigma_mm(const SimConfig& config, const SensorSpec* model) {
  if (config.noise_sigma_mm) return *config.noise_sigma_mm;
  if (model != nullptr && model->position_noise_sd_mm) return *model->position_noise_sd_mm;
  return kDefaultPositionNoiseSdMm;
}

void apply_motion_spec(SimConfig& c, const std::string& spec) {
  std::string m = spec;
  for (const char* prefix : {"horizontal/", "horizontal-", "vertical/", "vertical-"}) {
    const std::string p = prefix;
    if (m.rfind(p, 0) == 0) {
      c.orientation = p[0] == 'h' ? HandOrientation::kHorizontal : HandOrientation::kVertical;
      m = m.substr(p.size());
      break;
    }
  }
  if (m == "static" || m == "open")
    c.motion = HandMotion::kOpen;
  else if (m == "index")
    c.motion = HandMotion::kIndexFlexion;
  else if (m == "thumb")
    c.motion = HandMotion::kThumbFlexion;
  else if (m == "wrist" || m == "wrist-flexion")
    c.motion = HandMotion::kWristFlexion;
  else if (m == "wrist-extension")
    c.motion = HandMotion::kWristExtension;
  else if (std::error_code ec; std::filesystem::exists(spec, ec)) {
    c.pose_set_path = spec;
    return;
  } else {
    // Not a file either (a name too long for a path is simply not one: the throwing overload of
    // exists() escaped as a filesystem_error, found by the fuzzer). The message quotes the start.
    throw Error("unknown motion " + text::quoted_excerpt(spec) +
                ": use static, index, thumb or wrist (optionally horizontal/… or vertical/…), or a pose-set file");
  }
  c.pose_set_path.clear();
}

std::string motion_spec(const SimConfig& c) {
  if (!c.pose_set_path.empty()) return c.pose_set_path;
  std::string m;
  switch (c.motion) {
    case HandMotion::kOpen:
      m = "static";
      break;
    case HandMotion::kIndexFlexion:
      m = "index";
      break;
    case HandMotion::kThumbFlexion:
      m = "thumb";
      break;
    case HandMotion::kWristFlexion:
      m = "wrist";
      break;
    case HandMotion::kWristExtension:
      m = "wrist-extension";
      break;
  }
  return std::string(orientation_name(c.orientation)) + "/" + m;
}

namespace {

// The hand, its motion and the streams: rates, latency, noise, what the controllers see.
void read_hand_and_streams(JsonReader& r, SimConfig& c) {
  c.pose_set_rate_hz = r.number_or("pose_set_rate_hz", c.pose_set_rate_hz);
  c.motion_period_s = r.number_or("motion_period_s", c.motion_period_s);
  c.sway_mm = r.number_or("sway_mm", c.sway_mm);
  c.hand_length_mm = r.number_or("hand_length_mm", c.hand_length_mm);
  c.hand_breadth_mm = r.number_or("hand_breadth_mm", c.hand_breadth_mm);
  c.rate_min_hz = r.number_or("rate_min_hz", c.rate_min_hz);
  c.rate_max_hz = r.number_or("rate_max_hz", c.rate_max_hz);
  c.rate_wander = r.number_or("rate_wander", c.rate_wander);
  c.latency_min_ms = r.number_or("latency_min_ms", c.latency_min_ms);
  c.latency_max_ms = r.number_or("latency_max_ms", c.latency_max_ms);
  if (r.has("noise")) c.noise = r.at("noise").boolean();
  if (r.has("noise_sigma_mm")) {
    c.noise_sigma_mm = r.number("noise_sigma_mm");
    if (*c.noise_sigma_mm < 0) r.at("noise_sigma_mm").fail("must be ≥ 0 mm (leave it out for each model's own)");
  }
  if (r.has("fov_test")) c.fov_test = r.at("fov_test").boolean();
  c.range_mm = r.number_or("range_mm", c.range_mm);
  if (r.has("occlusion")) c.occlusion = r.at("occlusion").boolean();
  c.phalanx_radius_mm = r.number_or("phalanx_radius_mm", c.phalanx_radius_mm);
  c.internal_model_bias = r.number_or("internal_model_bias", c.internal_model_bias);
  if (r.has("axis_cut")) c.axis_cut = r.at("axis_cut").boolean();
  c.axis_cut_mm = r.number_or("axis_cut_mm", c.axis_cut_mm);
  if (r.has("elbow_error")) c.elbow_error = r.at("elbow_error").boolean();
  c.elbow_error_min_mm = r.number_or("elbow_error_min_mm", c.elbow_error_min_mm);
  c.elbow_error_max_mm = r.number_or("elbow_error_max_mm", c.elbow_error_max_mm);
}

// How far each controller is from where the layout says: none, the layout's, given per slot, or random.
void read_calibration_error(JsonReader& r, SimConfig& c) {
  if (r.has("calibration")) {
    const std::string cal = r.string("calibration");
    if (cal == "layout")
      c.calibration = SimConfig::Calibration::kLayout;
    else if (cal == "none")
      c.calibration = SimConfig::Calibration::kNone;
    else if (cal == "custom")
      c.calibration = SimConfig::Calibration::kCustom;
    else
      r.at("calibration").fail("expected \"layout\", \"none\" or \"custom\"");
  }
  if (r.has("calibration_offsets_mm")) {
    JsonReader offs = r.at("calibration_offsets_mm");
    offs.require_object();
    for (const auto& [slot, v] : offs.json().items()) {
      JsonReader e = offs.at(slot.c_str());
      if (e.array_size() != 3) e.fail("expected [x, y, z]");
      c.calibration_offsets_mm[slot] = {e.at(size_t{0}).number(), e.at(size_t{1}).number(), e.at(size_t{2}).number()};
    }
  }
  if (r.has("calibration_rotations_deg")) {
    JsonReader rots = r.at("calibration_rotations_deg");
    rots.require_object();
    for (const auto& [slot, v] : rots.json().items()) {
      JsonReader e = rots.at(slot.c_str());
      if (e.array_size() != 3) e.fail("expected [rx, ry, rz] in degrees");
      c.calibration_rotations_deg[slot] = {e.at(size_t{0}).number(), e.at(size_t{1}).number(),
                                           e.at(size_t{2}).number()};
    }
  }
  c.calibration_random_translation_mm =
      r.number_or("calibration_random_translation_mm", c.calibration_random_translation_mm);
  c.calibration_random_rotation_deg = r.number_or("calibration_random_rotation_deg", c.calibration_random_rotation_deg);
  if (c.calibration_random_translation_mm < 0) r.at("calibration_random_translation_mm").fail("must be ≥ 0");
  if (c.calibration_random_rotation_deg < 0 || c.calibration_random_rotation_deg > 180)
    r.at("calibration_random_rotation_deg").fail("must be between 0 and 180");
}

// Unplugs, serials, the stand-in model, the ground truth's rate and the device clock's start.
void read_rig_events(JsonReader& r, SimConfig& c) {
  if (r.has("unplugs")) {
    JsonReader u = r.at("unplugs");
    for (size_t i = 0; i < u.array_size(); ++i) {
      JsonReader e = u.at(i);
      e.only_keys({"slot", "at_s", "duration_s"});
      c.unplugs.push_back({e.string("slot"), e.number("at_s"), e.number_or("duration_s", 1.0)});
    }
  }
  c.serial_prefix = r.string_or("serial_prefix", c.serial_prefix);
  c.stand_in_model = r.string_or("stand_in_model", c.stand_in_model);
  if (!c.stand_in_model.empty() && !sensor_catalogue().find(c.stand_in_model)) {
    r.at("stand_in_model")
        .fail("unknown sensor model \"" + c.stand_in_model + "\" (known models: " + sensor_catalogue().known_ids() +
              ")");
  }
  c.truth_rate_hz = r.number_or("truth_rate_hz", c.truth_rate_hz);
  if (r.has("device_clock_start_us")) {
    // A clock in µs: beyond 2^53 a double no longer holds every whole µs, and beyond the int64 range
    // the conversion itself is undefined (a fuzzer's 1e19 found it).
    const double start_us = r.number("device_clock_start_us");
    if (!(start_us >= 0 && start_us <= 9007199254740992.0))
      r.at("device_clock_start_us").fail("must be between 0 and 2^53 µs (285 years)");
    c.device_clock_start_us = static_cast<std::int64_t>(start_us);
  }
}

// What no single key can say wrong alone.
void check_sim_config(JsonReader& r, const SimConfig& c) {
  if (!(c.rate_min_hz > 0) || c.rate_max_hz < c.rate_min_hz) r.fail("rate_min_hz must be > 0 and ≤ rate_max_hz");
  if (c.latency_max_ms < c.latency_min_ms || c.latency_min_ms < 0)
    r.fail("latency_min_ms must be ≥ 0 and ≤ latency_max_ms");
  if (c.elbow_error_max_mm < c.elbow_error_min_mm) r.fail("elbow_error_min_mm must be ≤ elbow_error_max_mm");
  if (!(c.truth_rate_hz > 0)) r.at("truth_rate_hz").fail("must be > 0");
  if (!(c.motion_period_s > 0)) r.at("motion_period_s").fail("must be > 0");
  if (!(c.pose_set_rate_hz > 0)) r.at("pose_set_rate_hz").fail("must be > 0");
}

}  // namespace

SimConfig sim_config_from_json(const nlohmann::json& j, const std::string& source) {
  SimConfig c;
  JsonReader r(j, source);
  r.require_object();
  // A misspelt switch ("noize": false) must not leave the behaviour on in silence.
  r.only_keys({"seed",
               "calibration_seed",
               "motion",
               "pose_set_rate_hz",
               "motion_period_s",
               "sway_mm",
               "hand_length_mm",
               "hand_breadth_mm",
               "rate_min_hz",
               "rate_max_hz",
               "rate_wander",
               "latency_min_ms",
               "latency_max_ms",
               "noise",
               "noise_sigma_mm",
               "fov_test",
               "range_mm",
               "occlusion",
               "phalanx_radius_mm",
               "internal_model_bias",
               "axis_cut",
               "axis_cut_mm",
               "elbow_error",
               "elbow_error_min_mm",
               "elbow_error_max_mm",
               "calibration",
               "calibration_offsets_mm",
               "calibration_rotations_deg",
               "calibration_random_translation_mm",
               "calibration_random_rotation_deg",
               "study_errors",
               "hand_model_error",
               "unplugs",
               "serial_prefix",
               "stand_in_model",
               "truth_rate_hz",
               "device_clock_start_us"});
  // The preset first, so that any key given beside it overrides one of its values.
  if (r.has("study_errors") && r.at("study_errors").boolean()) {
    c.study_errors = true;
    c.hand_model_error = study_errors_hand_model();
    c.calibration_random_translation_mm = kStudyCalibrationTranslationMm;
    c.calibration_random_rotation_deg = kStudyCalibrationRotationDeg;
  }
  if (r.has("hand_model_error"))
    c.hand_model_error = hand_model_error_from_json(r.at("hand_model_error"), c.hand_model_error);
  if (r.has("seed")) c.seed = static_cast<std::uint64_t>(r.at("seed").integer());
  if (r.has("calibration_seed")) c.calibration_seed = static_cast<std::uint64_t>(r.at("calibration_seed").integer());
  if (r.has("motion")) {
    try {
      apply_motion_spec(c, r.string("motion"));
    } catch (const Error& e) {
      r.at("motion").fail(e.what());
    }
  }
  read_hand_and_streams(r, c);
  read_calibration_error(r, c);
  read_rig_events(r, c);
  check_sim_config(r, c);
  return c;
}

nlohmann::json sim_config_to_json(const SimConfig& c) {
  nlohmann::json j;
  j["seed"] = c.seed;
  if (c.calibration_seed) j["calibration_seed"] = *c.calibration_seed;
  j["motion"] = motion_spec(c);
  j["pose_set_rate_hz"] = c.pose_set_rate_hz;
  j["motion_period_s"] = c.motion_period_s;
  j["sway_mm"] = c.sway_mm;
  j["hand_length_mm"] = c.hand_length_mm;
  j["hand_breadth_mm"] = c.hand_breadth_mm;
  j["rate_min_hz"] = c.rate_min_hz;
  j["rate_max_hz"] = c.rate_max_hz;
  j["rate_wander"] = c.rate_wander;
  j["latency_min_ms"] = c.latency_min_ms;
  j["latency_max_ms"] = c.latency_max_ms;
  j["noise"] = c.noise;
  // Only when configured: read back, a value would override every model's figure.
  if (c.noise_sigma_mm) j["noise_sigma_mm"] = *c.noise_sigma_mm;
  j["fov_test"] = c.fov_test;
  j["range_mm"] = c.range_mm;
  j["occlusion"] = c.occlusion;
  j["phalanx_radius_mm"] = c.phalanx_radius_mm;
  j["internal_model_bias"] = c.internal_model_bias;
  j["axis_cut"] = c.axis_cut;
  j["axis_cut_mm"] = c.axis_cut_mm;
  j["elbow_error"] = c.elbow_error;
  j["elbow_error_min_mm"] = c.elbow_error_min_mm;
  j["elbow_error_max_mm"] = c.elbow_error_max_mm;
  j["calibration"] = calibration_name(c.calibration);
  nlohmann::json offs = nlohmann::json::object();
  for (const auto& [slot, v] : c.calibration_offsets_mm) offs[slot] = {v.x(), v.y(), v.z()};
  j["calibration_offsets_mm"] = offs;
  nlohmann::json rots = nlohmann::json::object();
  for (const auto& [slot, v] : c.calibration_rotations_deg) rots[slot] = {v.x(), v.y(), v.z()};
  j["calibration_rotations_deg"] = rots;
  j["calibration_random_translation_mm"] = c.calibration_random_translation_mm;
  j["calibration_random_rotation_deg"] = c.calibration_random_rotation_deg;
  // Written only when used, so that sidecars of the default simulator stay as they were.
  if (c.study_errors) j["study_errors"] = true;
  if (c.hand_model_error.enabled || c.study_errors)
    j["hand_model_error"] = hand_model_error_to_json(c.hand_model_error);
  nlohmann::json unplugs = nlohmann::json::array();
  for (const auto& u : c.unplugs) unplugs.push_back({{"slot", u.slot}, {"at_s", u.at_s}, {"duration_s", u.duration_s}});
  j["unplugs"] = unplugs;
  j["serial_prefix"] = c.serial_prefix;
  if (!c.stand_in_model.empty()) j["stand_in_model"] = c.stand_in_model;
  j["truth_rate_hz"] = c.truth_rate_hz;
  j["device_clock_start_us"] = c.device_clock_start_us;
  return j;
}

SimConfig load_sim_config(const std::string& path) {
  return sim_config_from_json(read_json_file(path), path);
}

}  // namespace lmc::devices
