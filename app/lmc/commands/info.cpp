// lmc info FILE [--json]: what is in a recording, a TRC or C3D file or a layout, before anyone feeds it
// to processing. The file type is detected from the content, not the extension:
//   JSON object with "format": "lmc-session" → the recorder's sidecar LMC_<trial>.session.json
//   other JSON object with "format" → layout (core/io/layout_json.h)
//   first line "PathFileType…"  → TRC (core/io/trc.h)
//   second byte 0x50, binary    → C3D (core/io/c3d.h)
//   first line "Device ID…"     → LMC recording, any variant (core/io/lmc_recording.h)
//
// --json prints one object (rates in Hz, times in s, fractions 0..1; null when unknown); its keys per
// file type are listed in docs/cli.md, and for the terminal in --help below. A session sidecar is
// read through core/io/recorder_sidecar.h, whose tables are the only place its own keys are spelt.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/io/c3d.h"
#include "core/io/delimited_text.h"
#include "core/io/json_checked.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/recorder_sidecar.h"
#include "core/io/trc.h"
#include "core/processing/resample.h"
#include "core/stats/percentile.h"
#include "core/stats/stream_rates.h"

namespace {

using nlohmann::json;

constexpr const char* kJsonKeysHelp =
    "--json prints one object. Keys: file, type (recording|trc|c3d|layout|session), warnings[]; recording: variant, "
    "rows, "
    "hand_rows, device_count, device_ids[], duration_s, devices[{id, rows, hand_rows, hand_fraction, duration_s, "
    "rate_median_hz, rate_p5_hz, rate_p95_hz, reported_rate_median_hz, visibility_fraction (raytraced)}]; trc: "
    "markers, frames, data_rate_hz, camera_rate_hz, units, duration_s, missing_fraction, marker_stats[{name, "
    "missing_fraction}]; c3d: as trc without camera_rate_hz (marker_stats[] also with description), first_frame, "
    "storage, "
    "point_scale, processor, analog_per_frame, manufacturer{company, software, version}, parameters[]; layout: name, "
    "description, device_count, sensor{range_mm, fov_long_deg, fov_short_deg}, "
    "devices[{slot, serial, pose{x,y,z,rx,ry,rz}, offset_mm[3]}]; session (recorder sidecar): trial, status, error, "
    "backend, recording_file, layout_name, layout_device_count, host_start_utc, host_stop_utc, duration_s, "
    "serial_to_slot{}, frames_written, frames_dropped, devices[{device_id, slot, serial, frames_written, "
    "frames_with_hand, hand_fraction, frames_dropped_queue, frame_id_gaps, gaps, gap_ms, disconnects, "
    "first_timestamp_us, last_timestamp_us}], vicon_packets[{type, packet_id, target, datagrams_sent, error}], "
    "vicon_alignment, vicon_trigger_received, vicon_stop_received, vicon_listen{address, binding, allowed_senders, "
    "any_sender, trigger_host, refused_datagrams, refused_senders{}, warning}, stopped_by, trial_window, ground_truth. "
    "Unknown values are "
    "null.";

struct InfoOptions {
  std::string file;
  bool json = false;
};

json number_or_null(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << v;
  return s.str();
}

const char* variant_name(lmc::RecordingKind k) {
  switch (k) {
    case lmc::RecordingKind::kRaw:
      return "raw";
    case lmc::RecordingKind::kResampled:
      return "resampled";
    case lmc::RecordingKind::kRaytraced:
      return "raytraced";
  }
  return "unknown";
}

struct DeviceSummary {
  int id = 0;
  long rows = 0;
  long hand_rows = 0;
  double duration_s = std::nan("");
  double rate_median_hz = std::nan("");
  double rate_p5_hz = std::nan("");
  double rate_p95_hz = std::nan("");
  double reported_rate_median_hz = std::nan("");
  std::optional<std::array<double, lmc::kNumDigits>> visibility_fraction;
};

std::vector<DeviceSummary> summarise_devices(const lmc::LmcRecording& rec) {
  std::vector<DeviceSummary> out;
  for (const int id : rec.device_ids()) {
    DeviceSummary d;
    d.id = id;
    std::vector<std::int64_t> stamps;
    std::vector<double> reported;
    std::array<long, lmc::kNumDigits> visible{};
    for (size_t r = 0; r < rec.rows.size(); ++r) {
      const auto& row = rec.rows[r];
      if (row.device_id != id) continue;
      ++d.rows;
      stamps.push_back(row.timestamp_us);
      reported.push_back(row.frame_rate_hz);
      if (!row.hand_present) continue;
      ++d.hand_rows;
      if (rec.kind == lmc::RecordingKind::kRaytraced) {
        for (int f = 0; f < lmc::kNumDigits; ++f)
          visible[static_cast<size_t>(f)] += rec.visibility[r][static_cast<size_t>(f)] == 1;
      }
    }
    std::sort(stamps.begin(), stamps.end());
    d.reported_rate_median_hz = lmc::percentile(std::move(reported), 50);
    if (stamps.size() >= 2) d.duration_s = static_cast<double>(stamps.back() - stamps.front()) * 1e-6;
    // The rates as the trial verdict computes them, from this device's rows in time order.
    const lmc::StreamRates rates = lmc::stream_rates(stamps);
    d.rate_median_hz = rates.median_hz;
    d.rate_p5_hz = rates.p5_hz;
    d.rate_p95_hz = rates.p95_hz;
    if (rec.kind == lmc::RecordingKind::kRaytraced && d.hand_rows > 0) {
      std::array<double, lmc::kNumDigits> frac{};
      for (int f = 0; f < lmc::kNumDigits; ++f) {
        frac[static_cast<size_t>(f)] =
            static_cast<double>(visible[static_cast<size_t>(f)]) / static_cast<double>(d.hand_rows);
      }
      d.visibility_fraction = frac;
    }
    out.push_back(d);
  }
  return out;
}

void print_warnings(std::ostream& out, const std::vector<std::string>& warnings) {
  if (warnings.empty()) {
    out << "warnings:   none\n";
    return;
  }
  out << "warnings:   " << warnings.size() << "\n";
  for (const auto& w : warnings) out << "  - " << w << "\n";
}

// Rows with a hand and the span of the timestamps; the span in double: timestamps of a hostile
// file may lie far apart (the reader bounds them to ±2^53 µs).
struct RecordingSpan {
  long hand_rows = 0;
  double duration_s = std::nan("");
};
RecordingSpan recording_span(const lmc::LmcRecording& rec) {
  RecordingSpan span;
  std::int64_t t_min = 0;
  std::int64_t t_max = 0;
  for (size_t i = 0; i < rec.rows.size(); ++i) {
    span.hand_rows += rec.rows[i].hand_present ? 1 : 0;
    t_min = i == 0 ? rec.rows[i].timestamp_us : std::min(t_min, rec.rows[i].timestamp_us);
    t_max = i == 0 ? rec.rows[i].timestamp_us : std::max(t_max, rec.rows[i].timestamp_us);
  }
  if (rec.rows.size() >= 2) span.duration_s = (static_cast<double>(t_max) - static_cast<double>(t_min)) * 1e-6;
  return span;
}

// The resampler's plausibility rule (ResampleOptions): the recorder writes every controller
// frame, so far fewer rows than seconds means a timestamp jumped; say so before `lmc process`
// refuses the file. Empty when the duration is plausible.
std::string implausible_duration_warning(double duration_s, size_t rows) {
  const lmc::ResampleOptions limits;
  const double plausible_s = limits.min_plausible_span_s + limits.max_seconds_per_row * static_cast<double>(rows);
  if (!(duration_s > plausible_s)) return {};
  std::ostringstream w;
  w << "duration " << duration_s << " s is implausible for " << rows << " rows (at most " << plausible_s
    << " s expected): a timestamp likely jumps; lmc process will refuse this recording";
  return w.str();
}

json recording_device_json(const DeviceSummary& d) {
  json dj;
  dj["id"] = d.id;
  dj["rows"] = d.rows;
  dj["hand_rows"] = d.hand_rows;
  dj["hand_fraction"] = d.rows > 0 ? static_cast<double>(d.hand_rows) / static_cast<double>(d.rows) : 0.0;
  dj["duration_s"] = number_or_null(d.duration_s);
  dj["rate_median_hz"] = number_or_null(d.rate_median_hz);
  dj["rate_p5_hz"] = number_or_null(d.rate_p5_hz);
  dj["rate_p95_hz"] = number_or_null(d.rate_p95_hz);
  dj["reported_rate_median_hz"] = number_or_null(d.reported_rate_median_hz);
  if (d.visibility_fraction) {
    json v;
    for (int f = 0; f < lmc::kNumDigits; ++f) {
      v[std::string(lmc::digit_name(f))] = (*d.visibility_fraction)[static_cast<size_t>(f)];
    }
    dj["visibility_fraction"] = v;
  }
  return dj;
}

// The per-device table of the text form; ray-traced recordings add each finger's visible share.
void print_recording_devices(std::ostream& out, const std::vector<DeviceSummary>& devices, bool vis) {
  out << std::left << std::setw(8) << "device" << std::right << std::setw(7) << "rows" << std::setw(7) << "hand"
      << std::setw(8) << "hand%" << std::setw(12) << "duration_s" << std::setw(13) << "rate_med_hz" << std::setw(12)
      << "rate_p5_hz" << std::setw(13) << "rate_p95_hz" << std::setw(14) << "reported_hz";
  if (vis) out << "  visible% thumb/index/middle/ring/pinky";
  out << "\n";
  for (const auto& d : devices) {
    const double pct = d.rows > 0 ? 100.0 * static_cast<double>(d.hand_rows) / static_cast<double>(d.rows) : 0.0;
    out << std::left << std::setw(8) << d.id << std::right << std::setw(7) << d.rows << std::setw(7) << d.hand_rows
        << std::setw(8) << fixed(pct, 1) << std::setw(12) << fixed(d.duration_s, 3) << std::setw(13)
        << fixed(d.rate_median_hz, 2) << std::setw(12) << fixed(d.rate_p5_hz, 2) << std::setw(13)
        << fixed(d.rate_p95_hz, 2) << std::setw(14) << fixed(d.reported_rate_median_hz, 2);
    if (vis && d.visibility_fraction) {
      out << "  ";
      for (int f = 0; f < lmc::kNumDigits; ++f) {
        out << (f ? "/" : "") << fixed(100.0 * (*d.visibility_fraction)[static_cast<size_t>(f)], 0);
      }
    }
    out << "\n";
  }
}

void info_recording(const std::string& file, bool as_json, std::ostream& out) {
  const lmc::LmcRecording rec = lmc::read_lmc_recording(file);
  const auto devices = summarise_devices(rec);
  const RecordingSpan span = recording_span(rec);
  std::vector<std::string> warnings = rec.warnings;
  if (std::string w = implausible_duration_warning(span.duration_s, rec.rows.size()); !w.empty())
    warnings.push_back(std::move(w));

  if (as_json) {
    json j;
    j["file"] = file;
    j["type"] = "recording";
    j["variant"] = variant_name(rec.kind);
    j["rows"] = rec.rows.size();
    j["hand_rows"] = span.hand_rows;
    j["device_count"] = devices.size();
    j["device_ids"] = rec.device_ids();
    j["duration_s"] = number_or_null(span.duration_s);
    j["devices"] = json::array();
    for (const auto& d : devices) j["devices"].push_back(recording_device_json(d));
    j["warnings"] = warnings;
    out << j.dump(2) << "\n";
    return;
  }

  out << "file:       " << file << "\n";
  out << "type:       LMC recording (" << variant_name(rec.kind) << ")\n";
  out << "rows:       " << rec.rows.size() << " (" << span.hand_rows << " with a hand)\n";
  out << "devices:    " << devices.size();
  if (!devices.empty()) {
    out << " (";
    for (size_t i = 0; i < devices.size(); ++i) out << (i ? ", " : "") << devices[i].id;
    out << ")";
  }
  out << "\n";
  out << "duration:   " << fixed(span.duration_s, 3) << " s\n";
  if (!devices.empty()) {
    out << "\n";
    print_recording_devices(out, devices, rec.kind == lmc::RecordingKind::kRaytraced);
    out << "\n";
  }
  print_warnings(out, warnings);
}

void info_trc(const std::string& file, bool as_json, std::ostream& out) {
  const lmc::TrcData trc = lmc::read_trc(file);
  const int frames = trc.frame_count();
  std::vector<long> missing(static_cast<size_t>(trc.marker_count()), 0);
  long missing_all = 0;
  for (const auto& row : trc.positions) {
    for (size_t m = 0; m < row.size(); ++m) {
      const bool gone = row[m].array().isNaN().any();
      missing[m] += gone ? 1 : 0;
      missing_all += gone ? 1 : 0;
    }
  }
  const auto fraction = [&](long n, long of) {
    return of > 0 ? static_cast<double>(n) / static_cast<double>(of) : 0.0;
  };
  const double duration_s = trc.times_s.size() >= 2 ? trc.times_s.back() - trc.times_s.front() : std::nan("");
  const long samples = static_cast<long>(frames) * trc.marker_count();

  if (as_json) {
    json j;
    j["file"] = file;
    j["type"] = "trc";
    j["markers"] = trc.marker_count();
    j["frames"] = frames;
    j["data_rate_hz"] = trc.data_rate_hz;
    j["camera_rate_hz"] = trc.camera_rate_hz;
    j["units"] = trc.units;
    j["duration_s"] = number_or_null(duration_s);
    j["missing_fraction"] = fraction(missing_all, samples);
    j["marker_stats"] = json::array();
    for (int m = 0; m < trc.marker_count(); ++m) {
      j["marker_stats"].push_back({{"name", trc.marker_names[static_cast<size_t>(m)]},
                                   {"missing_fraction", fraction(missing[static_cast<size_t>(m)], frames)}});
    }
    j["warnings"] = trc.warnings;
    out << j.dump(2) << "\n";
    return;
  }
  out << "file:       " << file << "\n";
  out << "type:       TRC marker file\n";
  out << "markers:    " << trc.marker_count() << "\n";
  out << "frames:     " << frames << "\n";
  out << "rate:       " << trc.data_rate_hz << " Hz (camera " << trc.camera_rate_hz << " Hz)\n";
  out << "units:      " << trc.units << "\n";
  out << "duration:   " << fixed(duration_s, 3) << " s\n";
  out << "missing:    " << fixed(100.0 * fraction(missing_all, samples), 1) << " % of marker samples\n\n";
  size_t width = 6;
  for (const auto& n : trc.marker_names) width = std::max(width, n.size());
  out << std::left << std::setw(static_cast<int>(width) + 2) << "marker"
      << "missing%\n";
  for (int m = 0; m < trc.marker_count(); ++m) {
    out << std::left << std::setw(static_cast<int>(width) + 2) << trc.marker_names[static_cast<size_t>(m)] << std::right
        << std::setw(8) << fixed(100.0 * fraction(missing[static_cast<size_t>(m)], frames), 1) << "\n";
  }
  out << "\n";
  print_warnings(out, trc.warnings);
}

// A C3D file is described like a TRC (points are its markers), plus how it stores them and who
// wrote it (MANUFACTURER), so an exported file can be checked before it goes to another tool.
void info_c3d(const std::string& file, const std::string& bytes, bool as_json, std::ostream& out) {
  const lmc::C3dData c3d = lmc::parse_c3d(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), file);
  const int frames = c3d.frame_count();
  std::vector<long> missing(static_cast<size_t>(c3d.point_count()), 0);
  long missing_all = 0;
  for (const auto& row : c3d.positions) {
    for (size_t m = 0; m < row.size() && m < missing.size(); ++m) {
      const bool gone = row[m].array().isNaN().any();
      missing[m] += gone ? 1 : 0;
      missing_all += gone ? 1 : 0;
    }
  }
  const auto fraction = [&](long n, long of) {
    return of > 0 ? static_cast<double>(n) / static_cast<double>(of) : 0.0;
  };
  const double duration_s = frames >= 2 ? (frames - 1) / c3d.point_rate_hz : std::nan("");
  const long samples = static_cast<long>(frames) * c3d.point_count();
  const char* processor = c3d.processor == lmc::C3dProcessor::kIntel ? "intel"
                          : c3d.processor == lmc::C3dProcessor::kDec ? "dec"
                                                                     : "mips";
  const auto text_or_null_local = [](const std::string& s) { return s.empty() ? json(nullptr) : json(s); };

  if (as_json) {
    json j;
    j["file"] = file;
    j["type"] = "c3d";
    j["markers"] = c3d.point_count();
    j["frames"] = frames;
    j["first_frame"] = c3d.first_frame;
    j["data_rate_hz"] = c3d.point_rate_hz;
    j["units"] = c3d.units;
    j["storage"] = c3d.float_storage ? "float" : "integer";
    j["point_scale"] = c3d.point_scale;
    j["processor"] = processor;
    j["analog_per_frame"] = c3d.analog_per_frame;
    j["manufacturer"] = {{"company", text_or_null_local(c3d.manufacturer_company)},
                         {"software", text_or_null_local(c3d.manufacturer_software)},
                         {"version", text_or_null_local(c3d.manufacturer_version)}};
    j["duration_s"] = number_or_null(duration_s);
    j["missing_fraction"] = fraction(missing_all, samples);
    j["marker_stats"] = json::array();
    for (int m = 0; m < c3d.point_count(); ++m) {
      json stat{{"name", c3d.labels[static_cast<size_t>(m)]},
                {"missing_fraction", fraction(missing[static_cast<size_t>(m)], frames)}};
      if (static_cast<size_t>(m) < c3d.descriptions.size())
        stat["description"] = c3d.descriptions[static_cast<size_t>(m)];
      j["marker_stats"].push_back(stat);
    }
    j["parameters"] = c3d.parameter_names;
    j["warnings"] = c3d.warnings;
    out << j.dump(2) << "\n";
    return;
  }
  out << "file:       " << file << "\n";
  out << "type:       C3D motion file\n";
  out << "markers:    " << c3d.point_count() << "\n";
  out << "frames:     " << frames << " (first " << c3d.first_frame << ")\n";
  out << "rate:       " << c3d.point_rate_hz << " Hz\n";
  out << "units:      " << c3d.units << "\n";
  out << "storage:    " << (c3d.float_storage ? "float" : "integer") << " (POINT:SCALE " << c3d.point_scale << "), "
      << processor << " byte order\n";
  if (!c3d.manufacturer_company.empty() || !c3d.manufacturer_software.empty() || !c3d.manufacturer_version.empty()) {
    out << "written by: " << c3d.manufacturer_company
        << (c3d.manufacturer_software.empty() ? "" : ", " + c3d.manufacturer_software)
        << (c3d.manufacturer_version.empty() ? "" : ", version " + c3d.manufacturer_version) << "\n";
  }
  out << "duration:   " << fixed(duration_s, 3) << " s\n";
  out << "missing:    " << fixed(100.0 * fraction(missing_all, samples), 1) << " % of marker samples\n\n";
  size_t width = 6;
  for (const auto& n : c3d.labels) width = std::max(width, n.size());
  out << std::left << std::setw(static_cast<int>(width) + 2) << "marker"
      << "missing%\n";
  for (int m = 0; m < c3d.point_count(); ++m) {
    out << std::left << std::setw(static_cast<int>(width) + 2) << c3d.labels[static_cast<size_t>(m)] << std::right
        << std::setw(8) << fixed(100.0 * fraction(missing[static_cast<size_t>(m)], frames), 1) << "\n";
  }
  out << "\n";
  print_warnings(out, c3d.warnings);
}

void info_layout(const std::string& file, const json& doc, bool as_json, std::ostream& out) {
  const lmc::Layout layout = lmc::layout_from_json(doc, file);
  if (as_json) {
    json j;
    j["file"] = file;
    j["type"] = "layout";
    j["name"] = layout.name;
    j["description"] = layout.description;
    j["device_count"] = layout.device_count();
    // The shared sensor of a uniform rig; null for a mixed one (each device lists its own).
    j["sensor"] = lmc::uniform_sensors(layout) ? json{{"range_mm", layout.devices.front().sensor.range_mm},
                                                      {"fov_long_deg", layout.devices.front().sensor.fov_long_deg},
                                                      {"fov_short_deg", layout.devices.front().sensor.fov_short_deg}}
                                               : json(nullptr);
    j["devices"] = json::array();
    for (const auto& d : layout.devices) {
      j["devices"].push_back({{"slot", d.slot},
                              {"serial", d.serial ? json(*d.serial) : json(nullptr)},
                              {"model", d.model},
                              {"sensor",
                               {{"range_mm", d.sensor.range_mm},
                                {"range_near_mm", d.sensor.range_near_mm},
                                {"fov_long_deg", d.sensor.fov_long_deg},
                                {"fov_short_deg", d.sensor.fov_short_deg},
                                {"axis_cut_mm", d.sensor.axis_cut_mm}}},
                              {"pose",
                               {{"x", d.pose.x_mm},
                                {"y", d.pose.y_mm},
                                {"z", d.pose.z_mm},
                                {"rx", d.pose.rx_deg},
                                {"ry", d.pose.ry_deg},
                                {"rz", d.pose.rz_deg}}},
                              {"offset_mm", {d.offset_mm.x(), d.offset_mm.y(), d.offset_mm.z()}}});
    }
    j["warnings"] = json::array();
    out << j.dump(2) << "\n";
    return;
  }
  out << "file:       " << file << "\n";
  out << "type:       layout\n";
  out << "name:       " << layout.name << "\n";
  if (!layout.description.empty()) out << "about:      " << layout.description << "\n";
  if (lmc::uniform_sensors(layout)) {
    const lmc::SensorModel& s = layout.devices.front().sensor;
    out << "sensor:     range " << s.range_mm << " mm, field of view " << s.fov_long_deg << "° x " << s.fov_short_deg
        << "°\n";
  } else {
    for (const auto& d : layout.devices) {
      out << "sensor:     " << d.slot << " " << d.model << ", range " << d.sensor.range_mm << " mm, field of view "
          << d.sensor.fov_long_deg << "° x " << d.sensor.fov_short_deg << "°\n";
    }
  }
  out << "devices:    " << layout.device_count() << "\n\n";
  out << std::left << std::setw(7) << "slot" << std::setw(12) << "serial" << std::right;
  for (const char* h : {"x_mm", "y_mm", "z_mm", "rx_deg", "ry_deg", "rz_deg", "off_x", "off_y", "off_z"}) {
    out << std::setw(9) << h;
  }
  out << "\n";
  for (const auto& d : layout.devices) {
    out << std::left << std::setw(7) << d.slot << std::setw(12) << d.serial.value_or("-") << std::right;
    for (const double v : {d.pose.x_mm, d.pose.y_mm, d.pose.z_mm, d.pose.rx_deg, d.pose.ry_deg, d.pose.rz_deg,
                           d.offset_mm.x(), d.offset_mm.y(), d.offset_mm.z()}) {
      out << std::setw(9) << fixed(v, 2);
    }
    out << "\n";
  }
}

// The recorder's sidecar (sessions/README.md), read through core/io/recorder_sidecar.h: lenient
// for what a crashed or older recording leaves out (shown as "-" / null), an error for a value
// of the wrong type.
json value_or_null(const json& obj, const char* key) {
  return obj.is_object() && obj.contains(key) ? obj.at(key) : json(nullptr);
}

std::string text_of(const json& v) {
  if (v.is_null()) return "-";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

// An empty text field of the sidecar is an unknown value.
json text_or_null(const std::string& s) {
  return s.empty() ? json(nullptr) : json(s);
}

json sidecar_devices_json(const lmc::RecorderSidecar& side) {
  json devices = json::array();
  for (const auto& d : side.devices) {
    double gap_ms = 0;
    for (const auto& g : d.gaps) gap_ms += g.duration_ms();
    devices.push_back({{"device_id", d.device_id},
                       {"slot", d.slot},
                       {"serial", d.serial},
                       {"frames_written", d.frames_written},
                       {"frames_with_hand", d.frames_with_hand},
                       {"hand_fraction", d.frames_written > 0 ? json(static_cast<double>(d.frames_with_hand) /
                                                                     static_cast<double>(d.frames_written))
                                                              : json(nullptr)},
                       {"frames_dropped_queue", d.frames_dropped_queue},
                       {"frame_id_gaps", d.frame_id_gaps},
                       {"gaps", d.gaps.size()},
                       {"gap_ms", gap_ms},
                       {"disconnects", d.disconnects.size()},
                       {"first_timestamp_us", d.first_timestamp_us},
                       {"last_timestamp_us", d.last_timestamp_us}});
  }
  return devices;
}

json sidecar_packets_json(const lmc::RecorderSidecar& side) {
  json packets = json::array();
  for (const auto& p : side.vicon_packets)
    packets.push_back({{"type", text_or_null(p.type)},
                       {"packet_id", p.packet_id},
                       {"target", text_or_null(p.target)},
                       {"datagrams_sent", p.datagrams_sent},
                       {"error", text_or_null(p.error)}});
  return packets;
}

// What `lmc info` says of a sidecar, in both forms: the sidecar read, and what it lists worked out.
struct SidecarView {
  lmc::RecorderSidecar side;
  json layout_devices, layout_name, rec_file, devices, packets, serial_map, truth;
  double duration_s = 0;
  std::vector<std::string> warnings;
};

SidecarView sidecar_view(const std::string& file, const json& doc) {
  SidecarView v;
  v.side = lmc::recorder_sidecar_from_json(doc, file);
  const lmc::RecorderSidecar& side = v.side;
  v.layout_devices = value_or_null(side.layout, "devices");
  v.layout_name = value_or_null(side.layout, "name");
  v.duration_s = side.host_duration_s();
  if (!side.complete())
    v.warnings.push_back(
        "status is still \"recording\": the program stopped before the trial was closed (crash?); "
        "the recording holds the rows written until then");
  v.rec_file = text_or_null(side.recording_file);
  if (!side.recording_file.empty()) {
    const auto beside = std::filesystem::path(file).parent_path() / side.recording_file;
    if (!std::filesystem::exists(beside))
      v.warnings.push_back("recording file " + beside.string() + " not found beside the sidecar");
  }
  v.devices = sidecar_devices_json(side);
  v.packets = sidecar_packets_json(side);
  v.serial_map = lmc::serial_to_slot_json(side.serial_to_slot);
  v.truth = side.ground_truth ? lmc::sidecar_ground_truth_to_json(*side.ground_truth) : json(nullptr);
  return v;
}

void print_session_json(const std::string& file, const SidecarView& v, std::ostream& out) {
  const lmc::RecorderSidecar& side = v.side;
  json j;
  j["file"] = file;
  j["type"] = "session";
  j["trial"] = text_or_null(side.trial);
  j["status"] = text_or_null(side.status);
  j["error"] = text_or_null(side.error);
  j["backend"] = text_or_null(side.backend);
  j["recording_file"] = v.rec_file;
  j["layout_name"] = v.layout_name;
  j["layout_device_count"] = v.layout_devices.is_array() ? json(v.layout_devices.size()) : json(nullptr);
  j["host_start_utc"] = text_or_null(side.host_start_utc);
  j["host_stop_utc"] = text_or_null(side.host_stop_utc);
  j["duration_s"] = number_or_null(v.duration_s);
  j["serial_to_slot"] = v.serial_map;
  j["frames_written"] = side.frames_written;
  j["frames_dropped"] = side.frames_dropped;
  j["devices"] = v.devices;
  j["vicon_packets"] = v.packets;
  j["vicon_alignment"] = side.vicon_alignment;
  j["vicon_trigger_received"] = side.vicon_trigger_received;
  j["vicon_stop_received"] = side.vicon_stop_received;
  j["vicon_listen"] = side.vicon_listen ? lmc::sidecar_vicon_listen_to_json(*side.vicon_listen) : json(nullptr);
  j["stopped_by"] = text_or_null(side.stopped_by);
  j["trial_window"] = side.trial_window;
  j["ground_truth"] = v.truth;
  j["warnings"] = v.warnings;
  out << j.dump(2) << "\n";
}

// The Vicon lines: trigger packets sent, CaptureStart/Stop received, whom a listener obeyed.
void print_session_vicon(const SidecarView& v, std::ostream& out) {
  const lmc::RecorderSidecar& side = v.side;
  out << "vicon:      " << v.packets.size() << " trigger packet(s) sent";
  for (const auto& p : v.packets) {
    out << "\n  - " << text_of(p["type"]) << " PacketID " << text_of(p["packet_id"]) << " to " << text_of(p["target"])
        << " (" << text_of(p["datagrams_sent"]) << "x)";
    if (!p["error"].is_null()) out << " ERROR: " << text_of(p["error"]);
  }
  out << "\n";
  for (const json* got : {&side.vicon_trigger_received, &side.vicon_stop_received}) {
    if (!got->is_object()) continue;
    out << "vicon in:   " << (got == &side.vicon_stop_received ? "CaptureStop" : "CaptureStart") << " '"
        << text_of(value_or_null(*got, "name")) << "' PacketID " << text_of(value_or_null(*got, "packet_id"))
        << " received at " << text_of(value_or_null(*got, "host_time_utc")) << "\n";
  }
  if (const auto& l = side.vicon_listen) {
    out << "vicon from: " << (l->trigger_host.empty() ? std::string("no CaptureStart obeyed") : l->trigger_host)
        << " (listening on " << l->address << ", obeying "
        << (l->any_sender ? std::string("any sender") : l->allowed_senders) << ")\n";
    out << "refused:    " << l->refused_datagrams << " datagram(s) from other hosts";
    for (size_t i = 0; i < l->refused_senders.size(); ++i)
      out << (i == 0 ? ": " : ", ") << l->refused_senders[i].first << " x" << l->refused_senders[i].second;
    out << "\n";
    if (!l->warning.empty()) out << "warning:    " << l->warning << "\n";
  }
}

// The trial window, the Vicon clock alignment and the simulator's ground truth, when the sidecar has them.
void print_session_timing(const SidecarView& v, std::ostream& out) {
  const lmc::RecorderSidecar& side = v.side;
  if (const json& w = side.trial_window; w.is_object())
    out << "trial:      from go at " << text_of(value_or_null(w, "go_host_utc")) << " for "
        << text_of(value_or_null(w, "planned_s")) << " s; the countdown (" << text_of(value_or_null(w, "countdown_s"))
        << " s, " << text_of(value_or_null(w, "frames_before_go")) << " frames) is not in the file\n";
  const json& align = side.vicon_alignment;
  if (align.is_object()) {
    out << "alignment:  " << text_of(value_or_null(align, "event")) << " at "
        << text_of(value_or_null(align, "host_time_utc"));
    const json ad = value_or_null(align, "devices");
    if (ad.is_array())
      for (const auto& d : ad)
        out << "\n  - " << text_of(value_or_null(d, "slot")) << ": device clock "
            << text_of(value_or_null(d, "device_clock_at_event_us")) << " us (latest frame "
            << text_of(value_or_null(d, "latest_timestamp_us")) << " us)";
    out << "\n";
  }
  if (v.truth.is_object())
    out << "truth:      " << text_of(value_or_null(v.truth, "file")) << ", "
        << text_of(value_or_null(v.truth, "frames")) << " frames at " << text_of(value_or_null(v.truth, "rate_hz"))
        << " Hz, device clock at time 0 " << text_of(value_or_null(v.truth, "device_clock_at_time_zero_us")) << " us\n";
}

void print_session_devices(const json& devices, std::ostream& out) {
  if (devices.empty()) return;
  out << "\n"
      << std::left << std::setw(7) << "slot" << std::setw(22) << "serial" << std::right << std::setw(8) << "frames"
      << std::setw(8) << "hand%" << std::setw(9) << "dropped" << std::setw(9) << "id_gaps" << std::setw(6) << "gaps"
      << std::setw(10) << "gap_ms" << std::setw(13) << "disconnects"
      << "\n";
  for (const auto& d : devices) {
    const double pct = d["hand_fraction"].is_number() ? 100.0 * d["hand_fraction"].get<double>() : std::nan("");
    out << std::left << std::setw(7) << text_of(d["slot"]) << std::setw(22) << text_of(d["serial"]) << std::right
        << std::setw(8) << text_of(d["frames_written"]) << std::setw(8) << fixed(pct, 1) << std::setw(9)
        << text_of(d["frames_dropped_queue"]) << std::setw(9) << text_of(d["frame_id_gaps"]) << std::setw(6)
        << text_of(d["gaps"]) << std::setw(10) << fixed(d["gap_ms"].get<double>(), 0) << std::setw(13)
        << text_of(d["disconnects"]) << "\n";
  }
  out << "\n";
}

void info_session(const std::string& file, const json& doc, bool as_json, std::ostream& out) {
  const SidecarView v = sidecar_view(file, doc);
  if (as_json) {
    print_session_json(file, v, out);
    return;
  }
  const lmc::RecorderSidecar& side = v.side;
  out << "file:       " << file << "\n";
  out << "type:       session sidecar (lmc-session " << side.format_version << ")\n";
  out << "trial:      " << text_of(text_or_null(side.trial)) << "\n";
  out << "status:     " << text_of(text_or_null(side.status)) << "\n";
  if (!side.error.empty()) out << "error:      " << side.error << "\n";
  out << "backend:    " << text_of(text_or_null(side.backend)) << "\n";
  out << "recording:  " << text_of(v.rec_file) << "\n";
  out << "layout:     " << text_of(v.layout_name) << " ("
      << (v.layout_devices.is_array() ? std::to_string(v.layout_devices.size()) : std::string("?")) << " devices)\n";
  out << "started:    " << text_of(text_or_null(side.host_start_utc)) << "\n";
  out << "stopped:    " << text_of(text_or_null(side.host_stop_utc));
  if (std::isfinite(v.duration_s)) out << " (" << fixed(v.duration_s, 3) << " s)";
  out << "\n";
  out << "frames:     " << side.frames_written << " written, " << side.frames_dropped << " dropped\n";
  out << "serials:    ";
  if (v.serial_map.empty()) out << "-";
  bool first_serial = true;
  for (const auto& [serial, slot] : v.serial_map.items()) {
    out << (first_serial ? "" : ", ") << serial << " -> " << text_of(slot);
    first_serial = false;
  }
  out << "\n";
  print_session_vicon(v, out);
  if (!side.stopped_by.empty()) out << "stopped by: " << side.stopped_by << "\n";
  print_session_timing(v, out);
  print_session_devices(v.devices, out);
  print_warnings(out, v.warnings);
}

void run_info(const InfoOptions& opt) {
  const std::string& file = opt.file;
  const std::string bytes = lmc::text::read_file_bytes(file);
  if (lmc::text::is_blank(bytes)) throw lmc::Error(lmc::ErrorLocation{file, 1}, "empty file: nothing to describe");
  // C3D is binary: its second byte is 0x50 and its header block holds NULs, which no text file
  // this command knows has.
  if (bytes.size() >= 512 && static_cast<unsigned char>(bytes[1]) == 0x50 && bytes.find('\0') != std::string::npos) {
    info_c3d(file, bytes, opt.json, std::cout);
    return;
  }
  lmc::text::require_text(bytes, file);
  std::string_view head(bytes);
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
  const size_t first = head.find_first_not_of(" \t\r\n");
  if (head[first] == '{') {
    const json doc = lmc::parse_json_text(bytes, file);
    if (!doc.is_object() || !doc.contains("format")) {
      throw lmc::Error(lmc::ErrorLocation{file, 0, 0, "/format"},
                       "JSON file without \"format\": not a layout or session sidecar this version knows");
    }
    if (lmc::is_recorder_sidecar(doc)) {
      info_session(file, doc, opt.json, std::cout);
      return;
    }
    if (doc.at("format").is_string()) {
      throw lmc::Error(lmc::ErrorLocation{file, 0, 0, "/format"},
                       "unknown JSON format \"" + doc.at("format").get<std::string>() +
                           "\": expected a layout (format 1) or a session sidecar (\"lmc-session\")");
    }
    info_layout(file, doc, opt.json, std::cout);
    return;
  }
  const std::string_view first_line = head.substr(0, head.find('\n'));
  if (lmc::text::trim(first_line).rfind("PathFileType", 0) == 0) {
    info_trc(file, opt.json, std::cout);
    return;
  }
  if (lmc::text::normalise_name(first_line).rfind("device id", 0) == 0) {
    info_recording(file, opt.json, std::cout);
    return;
  }
  throw lmc::Error(lmc::ErrorLocation{file, 1, 1},
                   "unrecognised file: expected a layout (JSON with \"format\"), a TRC file (first line "
                   "'PathFileType …') or an LMC recording (header 'Device ID …')");
}

void setup_info(CLI::App& app) {
  auto opt = std::make_shared<InfoOptions>();
  app.add_option(
         "file", opt->file,
         "Recording (.txt), TRC (.trc), C3D (.c3d), layout (.json) or session sidecar (LMC_<trial>.session.json); type "
         "detected from content")
      ->required();
  app.add_flag("--json", opt->json, "Print one JSON object instead of text");
  app.footer(kJsonKeysHelp);
  app.callback([opt] { run_info(*opt); });
}

const lmc::cli::CommandRegistration info_command{
    "info", "Describe a recording, TRC, C3D, layout or session sidecar file", 10, setup_info};

}  // namespace
