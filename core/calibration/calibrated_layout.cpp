#include "core/calibration/calibrated_layout.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/common/number_format.h"

namespace lmc {

Layout calibrated_layout(const Layout& nominal, const CalibrationResult& result, const CalibrationSource& source) {
  Layout out = nominal;
  int changed = 0;
  for (size_t d = 0; d < out.devices.size() && d < result.devices.size(); ++d) {
    const DeviceCalibration& dc = result.devices[d];
    if (!dc.fitted) continue;
    LayoutDevice& ld = out.devices[d];
    ld.pose.set_rotation(dc.fitted_transform.r);
    ld.offset_mm = dc.fitted_transform.t - ld.pose.translation();
    ++changed;
  }
  out.name = nominal.name + " (calibrated)";
  std::string what =
      "Calibrated " + std::to_string(changed) + " of " + std::to_string(out.devices.size()) +
      " controllers from trial " + source.trial +
      (source.vicon.empty() ? " without Vicon (consensus of the controllers)" : " against Vicon file " + source.vicon) +
      " on " + source.when_utc + "; nominal layout: " + nominal.name + ".";
  out.description = nominal.description.empty() ? what : what + " " + nominal.description;
  return out;
}

namespace {

std::string mm(double v) {
  return std::isfinite(v) ? format_fixed(v, 1) : "-";
}

std::string before_after(const GroupResidual& r) {
  if (r.samples == 0) return "-";
  return mm(r.before_mm) + " > " + mm(r.after_mm);
}

}  // namespace

std::string residual_table(const CalibrationResult& result) {
  std::ostringstream o;
  o << "Residuals, RMS mm before > after calibration ("
    << (result.with_vicon ? "against Vicon" : "against the other controllers") << ")\n";
  o << std::left << std::setw(8) << "slot" << std::right << std::setw(8) << "samples" << std::setw(16) << "all points";
  for (int g = 0; g < kNumPointGroups; ++g) o << std::setw(18) << point_group_name(g);
  o << std::setw(10) << "moved mm" << std::setw(10) << "turned °"
    << "\n";
  for (const auto& d : result.devices) {
    o << std::left << std::setw(8) << d.slot << std::right << std::setw(8) << d.all.samples << std::setw(16)
      << before_after(d.all);
    for (const auto& g : d.groups) o << std::setw(18) << before_after(g);
    if (d.fitted) {
      o << std::setw(10) << format_fixed(d.moved_mm, 1) << std::setw(10) << format_fixed(d.turned_deg, 2);
    } else {
      o << std::setw(20) << "not calibrated";
    }
    o << "\n";
  }
  o << "Disagreement between controllers on co-visible points: " << mm(result.disagreement_before_mm) << " > "
    << mm(result.disagreement_after_mm) << " mm RMS (" << result.covisible_samples << " samples)\n";
  if (!result.with_vicon && result.sweeps > 0) o << "Consensus fit: " << result.sweeps << " sweeps\n";
  for (const auto& note : result.notes) o << "note: " << note << "\n";
  for (const auto& w : result.all_warnings()) o << "warning: " << w << "\n";
  return o.str();
}

}  // namespace lmc
