#include "core/processing/process_options_json.h"

#include "core/processing/length_correction_json.h"

namespace lmc {

nlohmann::json process_options_json(const ProcessOptions& o) {
  nlohmann::json j;
  j["method"] = fusion_method_name(o.method);
  const auto& r = o.resample;
  j["resample"] = {{"rate_hz", r.rate_hz},
                   {"max_gap_ms", r.max_gap_ms},
                   {"adaptive_gap", r.adaptive_gap},
                   {"gap_frame_intervals", r.gap_frame_intervals},
                   {"clock_reset_ms", r.clock_reset_ms},
                   {"grid_start_us", r.grid_start_us ? nlohmann::json(*r.grid_start_us) : nlohmann::json(nullptr)},
                   {"min_plausible_span_s", r.min_plausible_span_s},
                   {"max_seconds_per_row", r.max_seconds_per_row}};
  const auto& k = o.kalman;
  j["reference_kalman"] = {{"dt_s", k.dt_s},
                           {"q_position", k.q_position},
                           {"q_velocity", k.q_velocity},
                           {"p0_position", k.p0_position},
                           {"p0_velocity", k.p0_velocity},
                           {"window", k.window}};
  const auto& s = o.smoother;
  j["smoother"] = {{"revision", kDefaultFusionRevision}, {"dt_s", s.dt_s},
                   {"accel_psd", s.accel_psd},           {"noise_mm", s.noise_mm},
                   {"hidden_factor", s.hidden_factor},   {"axis_cut_factor", s.axis_cut_factor},
                   {"axis_cut_mm", s.axis_cut_mm},       {"axis_cut_margin_mm", s.axis_cut_margin_mm},
                   {"elbow_factor", s.elbow_factor},     {"max_gap_frames", s.max_gap_frames}};
  const auto& v = o.visibility;
  j["visibility"] = {{"range_mm", v.range_mm},
                     {"fov_long_deg", v.fov_long_deg},
                     {"fov_short_deg", v.fov_short_deg},
                     {"phalanx_radius_mm", v.phalanx_radius_mm}};
  j["trim_to_vicon"] = o.trim_to_vicon;
  j["max_lag_frames"] = o.max_lag_frames;
  j["min_vicon_seconds"] = o.min_vicon_seconds;
  // Only when given, so that every key made without one stays as it was.
  if (o.length_correction) j["length_correction"] = length_correction_json(*o.length_correction);
  return j;
}

}  // namespace lmc
