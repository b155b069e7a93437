#include "core/reports/coverage_report.h"

#include <algorithm>
#include <cstdio>

namespace lmc {
namespace {

std::string device_label(const std::vector<std::string>& slots, int d) {
  if (d < static_cast<int>(slots.size())) return slots[static_cast<size_t>(d)];
  return "device " + std::to_string(d + 1);
}

// One formatter per literal format (format strings are never variables, -Wformat=2).
std::string six_significant(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
std::string count_cell(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%8.0f", v);
  return buf;
}
std::string percent_cell(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%6.2f%%", v);
  return buf;
}
std::string fraction_cell(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "  %6.3f", v);
  return buf;
}

}  // namespace

std::string format_coverage(const Coverage& cov, const std::vector<std::string>& slots) {
  std::string out;
  out += "  frames " + std::to_string(cov.frames) + ", devices " + std::to_string(cov.devices) + "\n";
  out += "  M = " + six_significant(cov.metric) + "\n";
  out += "  c_i = frames whose worst-covered finger is seen by i devices:\n";
  for (size_t i = 0; i < cov.c.size(); ++i) {
    const double frac = cov.frames > 0 ? static_cast<double>(cov.c[i]) / static_cast<double>(cov.frames) : 0.0;
    const int bar = static_cast<int>(frac * 40.0 + 0.5);
    out += "    c_" + std::to_string(i) + " = " + count_cell(static_cast<double>(cov.c[i])) + "  " +
           percent_cell(100.0 * frac) + "  " + std::string(static_cast<size_t>(bar), '#') + "\n";
  }
  out += "  coverage (fraction of frames in which the device sees the finger):\n";
  out += "    device          thumb   index  middle    ring   pinky\n";
  for (int d = 0; d < cov.devices; ++d) {
    std::string name = device_label(slots, d);
    name.resize(std::max<size_t>(name.size(), 12), ' ');
    out += "    " + name;
    for (int k = 0; k < kNumDigits; ++k) out += fraction_cell(cov.device_finger_fraction(d, k));
    out += "\n";
  }
  out += "    seen by nobody";
  for (int k = 0; k < kNumDigits; ++k) out += fraction_cell(cov.finger_unseen_fraction(k));
  out += "\n";
  return out;
}

nlohmann::json coverage_to_json(const Coverage& cov, const std::vector<std::string>& slots) {
  nlohmann::json j;
  j["frames"] = cov.frames;
  j["devices"] = cov.devices;
  j["metric"] = cov.metric;
  j["c"] = cov.c;
  nlohmann::json devices = nlohmann::json::array();
  for (int d = 0; d < cov.devices; ++d) {
    nlohmann::json e;
    e["slot"] = device_label(slots, d);
    for (int k = 0; k < kNumDigits; ++k) e[std::string(digit_name(k))] = cov.device_finger_fraction(d, k);
    devices.push_back(e);
  }
  j["coverage"] = devices;
  nlohmann::json unseen, unseen_frames;
  for (int k = 0; k < kNumDigits; ++k) {
    unseen[std::string(digit_name(k))] = cov.finger_unseen_fraction(k);
    unseen_frames[std::string(digit_name(k))] = cov.finger_unseen[static_cast<size_t>(k)];
  }
  j["unseen"] = unseen;
  j["unseen_frames"] = unseen_frames;
  return j;
}

}  // namespace lmc
