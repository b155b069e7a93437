#include "core/results/trial_outputs.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/atomic_write.h"
#include "core/processing/trial_tag.h"

namespace lmc {

std::string format_fixed(double v, int decimals) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

namespace {

template <size_t N>
void row(std::ostringstream& o, const std::array<double, N>& v, int decimals = 6) {
  for (size_t k = 0; k < N; ++k) o << (k ? "\t" : "") << format_fixed(v[k], decimals);
  o << '\n';
}

void stats_block(std::ostringstream& o, const MeasureStats& s) {
  o << "Segment Length (min, max, average per row) in mm\n";
  for (int k = 0; k < kNumSegments; ++k) o << (k ? "\t" : "") << segment_name(k);
  o << '\n';
  row(o, s.segment_min);
  row(o, s.segment_max);
  row(o, s.segment_mean);
  o << "Finger Length (min, max, average per row) in mm\n";
  o << "Thumb\tFinger\tMiddle\tRing\tLittle\n";
  row(o, s.finger_min);
  row(o, s.finger_max);
  row(o, s.finger_mean);
  o << "Angle Joint (min, max, range of motion per row in degree)\n";
  // The authors' header row reuses the finger names; the six columns are index MCP, PIP, DIP,
  // thumb MCP, thumb DIP, wrist (measures.h).
  o << "Thumb\tFinger\tMiddle\tRing\tLittle\n";
  row(o, s.angle_min);
  row(o, s.angle_max);
  row(o, s.angle_rom);
}

// The authors' "Filename:" line is the file name without its extension. Our own stage suffixes
// (`.raw`, `.resampled`, `.raytraced`) go too, so every variant of one trial names it the same.
std::string stem_of(const std::string& path, const std::string& fallback) {
  if (path.empty()) return fallback;
  return without_stage_suffix(std::filesystem::path(path).stem().string());
}

nlohmann::json arr(const double* v, size_t n) {
  auto j = nlohmann::json::array();
  for (size_t k = 0; k < n; ++k) j.push_back(std::isfinite(v[k]) ? nlohmann::json(v[k]) : nlohmann::json(nullptr));
  return j;
}
template <size_t N>
nlohmann::json arr(const std::array<double, N>& v) {
  return arr(v.data(), N);
}

nlohmann::json stats_json(const MeasureStats& s) {
  nlohmann::json j;
  j["segment_names"] = nlohmann::json::array();
  for (int k = 0; k < kNumSegments; ++k) j["segment_names"].push_back(std::string(segment_name(k)));
  j["segment_min_mm"] = arr(s.segment_min);
  j["segment_max_mm"] = arr(s.segment_max);
  j["segment_mean_mm"] = arr(s.segment_mean);
  j["finger_names"] = {"thumb", "index", "middle", "ring", "pinky"};
  j["finger_min_mm"] = arr(s.finger_min);
  j["finger_max_mm"] = arr(s.finger_max);
  j["finger_mean_mm"] = arr(s.finger_mean);
  j["angle_names"] = nlohmann::json::array();
  for (int k = 0; k < kNumAngles; ++k) j["angle_names"].push_back(std::string(angle_name(k)));
  j["angle_min_deg"] = arr(s.angle_min);
  j["angle_max_deg"] = arr(s.angle_max);
  j["angle_rom_deg"] = arr(s.angle_rom);
  return j;
}

}  // namespace

std::string format_results_text(const TrialResult& r) {
  std::ostringstream o;
  const std::string bar(72, '_');
  o << bar << "LMC Data" << bar << '\n';
  o << "Filename:\t" << stem_of(r.lmc_source, r.tag.trial) << '\n';
  stats_block(o, r.lmc_stats);
  o << '\n';
  for (const auto& v : r.visibility) {
    o << "Visibility LMC" << v.device_id << '\n';
    o << "Thumb\tFinger\tMiddle\tRing\tLittle\n";
    std::array<double, kNumDigits> a{}, b{}, c{};
    for (size_t k = 0; k < kNumDigits; ++k) {
      a[k] = v.n_no_hand[k];
      b[k] = v.n_hidden[k];
      c[k] = v.n_visible[k];
    }
    row(o, a, 2);
    row(o, b, 2);
    row(o, c, 2);
    row(o, v.rate, 2);
  }
  o << "\n\n";
  if (r.has_vicon) {
    o << bar << "VICON Data" << bar << '\n';
    o << "Filename:\t" << stem_of(r.vicon_source, r.tag.trial) << '\n';
    stats_block(o, r.vicon_stats);
    o << "\n\n";
  }
  return o.str();
}

std::string format_measures_tsv(const TrialResult& r) {
  std::ostringstream o;
  o << "frame\ttime_s";
  auto names = [&](const char* prefix) {
    for (int k = 0; k < kNumSegments; ++k) o << '\t' << prefix << "segment_" << segment_name(k) << "_mm";
    static const char* fingers[] = {"thumb", "index", "middle", "ring", "pinky"};
    for (const char* f : fingers) o << '\t' << prefix << "finger_" << f << "_mm";
    for (int k = 0; k < kNumAngles; ++k) o << '\t' << prefix << "angle_" << angle_name(k) << "_deg";
  };
  names("lmc_");
  if (r.has_vicon) names("vicon_");
  for (const auto& d : r.device_frame.devices) {
    for (int k = 0; k < kNumDigits; ++k) o << "\tvis_LMC" << d.device_id << '_' << digit_name(k);
  }
  o << '\n';
  auto values = [&](const FrameMeasures& m) {
    for (double v : m.segment_mm) o << '\t' << format_fixed(v, 4);
    for (double v : m.finger_mm) o << '\t' << format_fixed(v, 4);
    for (double v : m.angle_deg) o << '\t' << format_fixed(v, 4);
  };
  for (size_t f = 0; f < r.lmc_frames.size(); ++f) {
    o << f << '\t' << format_fixed(static_cast<double>(f) * 0.01, 2);
    values(r.lmc_frames[f]);
    if (r.has_vicon) {
      if (f < r.vicon_frames.size()) {
        values(r.vicon_frames[f]);
      } else {
        for (int k = 0; k < kNumSegments + kNumFingers + kNumAngles; ++k) o << "\tnan";
      }
    }
    for (const auto& lab : r.labels) {
      for (int k = 0; k < kNumDigits; ++k) o << '\t' << static_cast<int>(lab[f][static_cast<size_t>(k)]);
    }
    o << '\n';
  }
  return o.str();
}

std::string format_fused_points(const TrialResult& r) {
  LmcRecording rec;
  rec.kind = RecordingKind::kResampled;
  for (int f = 0; f < r.fused.frame_count; ++f) {
    HandFrame hf;
    hf.device_id = 1;  // one fused stream; the reader accepts ids 1…8 only
    hf.frame_id = 0;
    hf.frame_rate_hz = 100;
    hf.timestamp_us = r.device_frame.start_us + static_cast<std::int64_t>(std::llround(f * r.device_frame.step_us));
    hf.hand_present = r.fused.has_hand(f);
    for (int i = 0; i < kNumHandPoints; ++i) hf.point(i) = r.fused.at(f, i);
    rec.rows.push_back(hf);
  }
  std::ostringstream o;
  write_lmc_recording(o, rec);
  return o.str();
}

nlohmann::json trial_summary_json(const TrialResult& r) {
  nlohmann::json j;
  j["format"] = 1;
  j["trial"] = r.tag.trial;
  j["tag"] = {{"layout", r.tag.layout}, {"pose", r.tag.pose}, {"motion", r.tag.motion}, {"repetition", r.tag.repetition},
              {"parsed", r.tag.parsed}};
  j["lmc_file"] = r.lmc_source;
  j["vicon_file"] = r.has_vicon ? nlohmann::json(r.vicon_source) : nlohmann::json(nullptr);
  j["method"] = fusion_method_name(r.method);
  j["layout"] = r.layout_name;
  j["layout_source"] = r.layout_source;
  j["input_kind"] = r.input_kind == RecordingKind::kRaw ? "raw" : r.input_kind == RecordingKind::kResampled ? "resampled" : "raytraced";
  j["frames"] = r.fused.frame_count;
  j["lmc_frames_before_trim"] = r.lmc_frames_before_trim;
  j["warnings"] = r.warnings;
  j["lmc"] = stats_json(r.lmc_stats);
  auto vis = nlohmann::json::array();
  for (const auto& v : r.visibility) {
    nlohmann::json d;
    d["device"] = "LMC" + std::to_string(v.device_id);
    d["no_hand"] = v.n_no_hand;
    d["hidden"] = v.n_hidden;
    d["visible"] = v.n_visible;
    d["rate"] = arr(v.rate);
    vis.push_back(d);
  }
  j["visibility"] = vis;
  auto streams = nlohmann::json::array();
  for (const auto& s : r.resample.devices) {
    streams.push_back({{"device", "LMC" + std::to_string(s.device_id)},
                       {"rows", s.rows},
                       {"hand_rows", s.hand_rows},
                       {"mean_rate_hz", s.mean_rate_hz},
                       {"out_of_order", s.out_of_order},
                       {"duplicates", s.duplicates},
                       {"clock_resets", s.clock_resets},
                       {"gaps", s.gaps},
                       {"gap_limit_ms", s.gap_limit_ms},
                       {"median_interval_ms", s.median_interval_ms}});
  }
  j["streams"] = streams;
  if (r.has_vicon) {
    j["vicon"] = stats_json(r.vicon_stats);
    j["vicon_frames_before_trim"] = r.vicon_frames_before_trim;
    const auto& c = r.comparison;
    j["comparison"] = {{"frames", c.frames},
                       {"lag", {{"valid", c.lag.valid}, {"clear", c.lag.clear}, {"frames", c.lag.lag_frames}, {"ms", c.lag.lag_frames * 10},
                                {"correlation", c.lag.correlation}}},
                       {"finger_diff_mean_mm", arr(c.finger_diff_mean)},
                       {"finger_diff_sd_mm", arr(c.finger_diff_sd)},
                       {"finger_mean_diff_mm", arr(c.finger_mean_diff)},
                       {"angle_diff_mean_deg", arr(c.angle_diff_mean)},
                       {"angle_diff_sd_deg", arr(c.angle_diff_sd)},
                       {"rom_diff_deg", arr(c.rom_diff)}};
  }
  return j;
}

std::filesystem::path write_trial_outputs(const TrialResult& r, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const std::string base = r.tag.trial;
  write_file_atomically(dir / (base + ".results.txt"), format_results_text(r));
  write_file_atomically(dir / (base + ".measures.tsv"), format_measures_tsv(r));
  write_file_atomically(dir / (base + ".fused.txt"), format_fused_points(r));
  const auto summary = dir / (base + ".summary.json");
  write_file_atomically(summary, trial_summary_json(r).dump(2) + "\n");
  return summary;
}

}  // namespace lmc
