#include "core/review/trial_series.h"

#include <charconv>
#include <cmath>

#include "core/common/nan.h"
#include "core/hand/hand_frame.h"

namespace lmc {
namespace {

void fill_measures(const std::vector<FrameMeasures>& frames, int n, MeasureSeries& out) {
  for (auto& v : out.angle_deg) v.assign(static_cast<size_t>(n), kNaN);
  for (auto& v : out.finger_mm) v.assign(static_cast<size_t>(n), kNaN);
  const int m = std::min(n, static_cast<int>(frames.size()));
  for (int f = 0; f < m; ++f) {
    for (int a = 0; a < kNumAngles; ++a) out.angle_deg[a][f] = frames[f].angle_deg[a];
    for (int k = 0; k < kNumFingers; ++k) out.finger_mm[k][f] = frames[f].finger_mm[k];
  }
}

// Locale-independent and short: plots need no more than 0.0001 of a mm or a degree.
void append_cell(std::string& out, double v) {
  if (!std::isfinite(v)) return;  // an empty cell, never 0
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 4);
  out.append(buf, r.ptr);
}

void append_measure_header(std::string& out, const std::string& prefix) {
  for (int a = 0; a < kNumAngles; ++a) out += "," + prefix + "_" + std::string(angle_name(a)) + "_deg";
  for (int f = 0; f < kNumDigits; ++f) out += "," + prefix + "_" + std::string(digit_name(f)) + "_length_mm";
}

void append_measure_row(std::string& out, const MeasureSeries& m, size_t f) {
  for (const auto& v : m.angle_deg) {
    out += ',';
    if (f < v.size()) append_cell(out, v[f]);
  }
  for (const auto& v : m.finger_mm) {
    out += ',';
    if (f < v.size()) append_cell(out, v[f]);
  }
}

}  // namespace

const char* label_word(std::int8_t label) {
  return label > 0 ? "seen" : label == 0 ? "internal model" : "no hand";
}

TrialSeries trial_series(const TrialAnalysis& r) {
  TrialSeries s;
  s.trial = r.tag.trial;
  const int n = r.fused.frame_count;
  s.time_s.resize(static_cast<size_t>(n));
  for (int f = 0; f < n; ++f) s.time_s[f] = r.world.time_s(f);
  fill_measures(r.lmc_frames, n, s.fused);
  s.has_vicon = r.has_vicon;
  if (r.has_vicon) fill_measures(r.vicon_frames, n, s.vicon);
  for (size_t d = 0; d < r.world.devices.size(); ++d) {
    DeviceSeries dev;
    dev.device_id = r.world.devices[d].device_id;
    fill_measures(measure_track(r.world.devices[d].track), n, dev.measures);
    for (auto& l : dev.label) l.assign(static_cast<size_t>(n), std::int8_t{-1});
    if (d < r.labels.size()) {
      const int m = std::min(n, static_cast<int>(r.labels[d].size()));
      for (int f = 0; f < m; ++f) {
        for (int k = 0; k < kNumDigits; ++k) dev.label[k][f] = r.labels[d][f][k];
      }
    }
    s.devices.push_back(std::move(dev));
  }
  return s;
}

std::string trial_series_csv(const TrialSeries& s) {
  std::string out = "time_s";
  append_measure_header(out, "fused");
  if (s.has_vicon) append_measure_header(out, "vicon");
  for (const auto& d : s.devices) append_measure_header(out, "lmc" + std::to_string(d.device_id));
  for (const auto& d : s.devices) {
    for (int f = 0; f < kNumDigits; ++f)
      out += ",lmc" + std::to_string(d.device_id) + "_" + std::string(digit_name(f)) + "_label";
  }
  out += '\n';
  for (size_t f = 0; f < s.time_s.size(); ++f) {
    append_cell(out, s.time_s[f]);
    append_measure_row(out, s.fused, f);
    if (s.has_vicon) append_measure_row(out, s.vicon, f);
    for (const auto& d : s.devices) append_measure_row(out, d.measures, f);
    for (const auto& d : s.devices) {
      // Appended in two steps: `"," + std::to_string(...)` made GCC 12's Release build warn
      // (a false -Wstringop-overflow in the inlined string concatenation).
      for (const auto& l : d.label) {
        out += ',';
        out += std::to_string(static_cast<int>(l[f]));
      }
    }
    out += '\n';
  }
  return out;
}

}  // namespace lmc
