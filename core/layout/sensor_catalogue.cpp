#include "core/layout/sensor_catalogue.h"

#include <algorithm>
#include <cstdio>

#include "core/common/error.h"

namespace lmc {

const SensorSpec* SensorCatalogue::find(const std::string& id) const {
  for (const auto& m : models) {
    if (m.id == id) return &m;
  }
  return nullptr;
}

const SensorSpec& SensorCatalogue::at(const std::string& id, const std::string& where) const {
  if (const SensorSpec* m = find(id)) return *m;
  throw Error(ErrorLocation{where}, "unknown sensor model \"" + id + "\" (known models: " + known_ids() + ")");
}

std::string SensorCatalogue::known_ids() const {
  std::string s;
  for (const auto& m : models) s += (s.empty() ? "" : ", ") + m.id;
  return s;
}

const SensorSpec* SensorCatalogue::for_product_id(std::uint32_t pid) const {
  for (const auto& m : models) {
    if (m.id == kStudySensorId) continue;
    if (std::find(m.leapc_product_ids.begin(), m.leapc_product_ids.end(), pid) != m.leapc_product_ids.end()) return &m;
  }
  return nullptr;
}

const SensorSpec* SensorCatalogue::matching(const SensorModel& sensor) const {
  if (const SensorSpec* s = find(kStudySensorId); s && s->sensor == sensor) return s;
  for (const auto& m : models) {
    if (m.sensor == sensor) return &m;
  }
  return nullptr;
}

std::string slot_model_mismatch(const std::string& slot, const std::string& slot_model, std::uint32_t product_id,
                                const SensorCatalogue& catalogue) {
  if (product_id == 0) return {};
  const SensorSpec* laid_out = catalogue.find(slot_model);
  if (!laid_out) return {};
  const auto& ids = laid_out->leapc_product_ids;
  if (std::find(ids.begin(), ids.end(), product_id) != ids.end()) return {};
  const SensorSpec* connected = catalogue.for_product_id(product_id);
  char pid[16];
  std::snprintf(pid, sizeof pid, "0x%04X", product_id);
  const std::string what = connected ? connected->name + " (" + connected->id + ")" : "product id " + std::string(pid);
  return slot + " is laid out as a " + laid_out->name + " (" + laid_out->id + ") but a " + what +
         " is connected to it: its field of view and range differ, so the layout's visibility does not hold; "
         "change the slot's model in the Layout tab or connect the right controller";
}

}  // namespace lmc
