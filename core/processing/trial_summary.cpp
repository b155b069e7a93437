#include "core/processing/trial_summary.h"

#include <array>
#include <cmath>
#include <string>

#include "core/processing/length_correction_json.h"

namespace lmc {

namespace {

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

nlohmann::json trial_summary_json(const TrialAnalysis& r) {
  nlohmann::json j;
  j["format"] = 1;
  j["trial"] = r.tag.trial;
  j["tag"] = {{"layout", r.tag.layout},
              {"pose", r.tag.pose},
              {"motion", r.tag.motion},
              {"repetition", r.tag.repetition},
              {"parsed", r.tag.parsed}};
  j["lmc_file"] = r.lmc_source;
  j["vicon_file"] = r.has_vicon ? nlohmann::json(r.vicon_source) : nlohmann::json(nullptr);
  j["method"] = fusion_method_name(r.method);
  if (r.length_correction) j["length_correction"] = length_correction_json(*r.length_correction);
  j["layout"] = r.layout_name;
  j["layout_source"] = r.layout_source;
  j["input_kind"] = r.input_kind == RecordingKind::kRaw         ? "raw"
                    : r.input_kind == RecordingKind::kResampled ? "resampled"
                                                                : "raytraced";
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
                       {"lag",
                        {{"valid", c.lag.valid},
                         {"clear", c.lag.clear},
                         {"frames", c.lag.lag_frames},
                         {"ms", c.lag.lag_frames * 10},
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

}  // namespace lmc
