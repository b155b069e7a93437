#pragma once
// The controller models a layout can name (assets/sensors/sensors.json): per model what the engine
// uses (SensorModel: field of view, near and far range, axis cut) and what the rest of the
// workbench shows or simulates (name, nominal frame rate, case footprint, where the device origin
// sits on the case, the LeapC product ids that identify it, how far a still point's reported position
// scatters where the literature says). The "study" entry is the study's own model (600 mm,
// 150°×120°), what every layout without a model uses.
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/layout/sensor_model.h"

namespace lmc {

inline constexpr const char* kStudySensorId = "study";

// The position noise (SD per axis, mm) the simulated rig gives a model with no published figure
// (the study's model, ir170): the simulator's own figure, which every rig of the study's model has
// always been simulated with.
inline constexpr double kDefaultPositionNoiseSdMm = 1.0;

struct SensorSpec {
  std::string id;    // "study", "lmc", "lmc2", "ir170": what layout files name
  std::string name;  // "Leap Motion Controller 2"
  SensorModel sensor;
  double frame_rate_hz = 120.0;
  Eigen::Vector3d footprint_mm = Eigen::Vector3d(80, 30, 11.3);  // width (x) × depth (z) × height (y)
  // The device origin from the centre of the case's bottom face, device axes (mm).
  Eigen::Vector3d origin_in_case_mm = Eigen::Vector3d(0, 11.3, 0);
  std::vector<std::uint32_t> leapc_product_ids;
  // How far a still point's reported position scatters, as an SD per axis (mm); empty where no
  // figure is published (ir170) or where the model is the study's. The simulated rig uses it as
  // this model's noise.
  std::optional<double> position_noise_sd_mm;

  bool operator==(const SensorSpec&) const = default;
};

struct SensorCatalogue {
  std::filesystem::path source;  // the file it was read from
  std::vector<SensorSpec> models;

  // The model with this id, or nullptr.
  const SensorSpec* find(const std::string& id) const;
  // Like find, but throws lmc::Error naming `where` (file, device) and the known ids.
  const SensorSpec& at(const std::string& id, const std::string& where) const;
  // The ids, comma-separated, for messages ("study, lmc, lmc2, ir170").
  std::string known_ids() const;
  // The first model (file order) whose product ids include `pid`, skipping "study" (the study's
  // model of the same hardware); nullptr when none does.
  const SensorSpec* for_product_id(std::uint32_t pid) const;
  // The model whose SensorModel equals `sensor` exactly ("study" first), or nullptr.
  const SensorSpec* matching(const SensorModel& sensor) const;
};

// The warning for a connected controller whose LeapC product id is not one of its slot's model's
// ("LMC3 is laid out as a Leap Motion Controller 2 but a Leap Motion Controller is connected: …"),
// or "" when it matches or the product id is unknown (0).
std::string slot_model_mismatch(const std::string& slot, const std::string& slot_model, std::uint32_t product_id,
                                const SensorCatalogue& catalogue);

}  // namespace lmc
