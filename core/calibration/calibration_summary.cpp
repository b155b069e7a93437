#include "core/calibration/calibration_summary.h"

#include <cmath>

namespace lmc {
namespace {

nlohmann::json summary_number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json calibration_summary_json(const CalibrationResult& r) {
  nlohmann::json devices = nlohmann::json::array();
  for (const auto& d : r.devices) {
    devices.push_back({{"slot", d.slot},
                       {"fitted", d.fitted},
                       {"samples", d.all.samples},
                       {"samples_beyond_axis_cut", d.beyond_cut},
                       {"samples_left_out_beyond_axis_cut", d.dropped_beyond_cut},
                       {"rms_before_mm", summary_number(d.all.before_mm)},
                       {"rms_after_mm", summary_number(d.all.after_mm)},
                       {"moved_mm", summary_number(d.moved_mm)},
                       {"turned_deg", summary_number(d.turned_deg)},
                       {"warnings", d.warnings}});
  }
  return {{"with_vicon", r.with_vicon},
          {"disagreement_before_mm", summary_number(r.disagreement_before_mm)},
          {"disagreement_after_mm", summary_number(r.disagreement_after_mm)},
          {"warnings", r.warnings},
          {"devices", devices}};
}

}  // namespace lmc
