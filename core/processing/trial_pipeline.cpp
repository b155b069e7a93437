#include "core/processing/trial_pipeline.h"

#include "core/common/error.h"
#include "core/processing/realign.h"
#include "core/processing/visibility_labels.h"

namespace lmc {

const char* fusion_method_name(FusionMethod m) {
  return m == FusionMethod::kReference ? "reference" : "default";
}

FusionMethod fusion_method_from_name(const std::string& name) {
  if (name == "reference") return FusionMethod::kReference;
  if (name == "default") return FusionMethod::kDefault;
  throw Error("unknown fusion method '" + name + "' (expected reference or default)");
}

namespace {

// The reference method is the study's algorithm, reproduced byte for byte; a correction fitted on
// the default fusion's lengths would silently turn it into something else.
void refuse_length_correction_with_reference(const ProcessOptions& options) {
  if (options.length_correction && options.method == FusionMethod::kReference) {
    throw Error(
        "a length correction applies to the default fusion only (the reference method stays the study's "
        "algorithm): drop the length correction or use the default method");
  }
}

void trim_grid(GridTrial& g, int frames) {
  if (frames >= g.frame_count) return;
  g.frame_count = frames;
  for (auto& d : g.devices) d.track.resize(frames);
}

// Steps 4–6 on a result whose steps 1–3 are done (resampled grid, labels, world tracks, and the
// trimmed Vicon in r.vicon when there is one).
void fuse_measure_compare(TrialAnalysis& r, const std::string& trial_name, const ProcessOptions& options) {
  // 4. Fuse.
  std::vector<const HandTrack*> tracks;
  for (const auto& d : r.world.devices) tracks.push_back(&d.track);
  if (options.method == FusionMethod::kReference) {
    r.fused = fuse_reference(tracks, options.kalman);
  } else {
    std::vector<std::vector<float>> quality(r.device_frame.devices.size());
    std::vector<const std::vector<float>*> qptr;
    for (size_t d = 0; d < quality.size(); ++d) {
      quality[d] = sample_quality(r.device_frame.devices[d].track, r.labels[d], options.smoother);
      qptr.push_back(&quality[d]);
    }
    r.fused = fuse_default(tracks, qptr, options.smoother);
  }

  // 4'. Per-subject length correction (only when asked).
  if (options.length_correction) {
    apply_length_correction(r.fused, *options.length_correction);
    r.length_correction = options.length_correction;
    if (options.length_correction->fit_trial == trial_name) {
      r.warnings.push_back(
          "the length correction was fitted on this trial: its lengths here are not an independent test");
    }
  }

  // 5. Measures.
  r.lmc_frames = measure_track(r.fused);
  r.lmc_stats = summarize(r.lmc_frames);

  // 6. Compare.
  if (r.has_vicon) {
    r.vicon_frames = measure_track(r.vicon);
    r.vicon_stats = summarize(r.vicon_frames);
    r.comparison = compare_measures(r.lmc_frames, r.lmc_stats, r.vicon_frames, r.vicon_stats);
    r.comparison.lag = estimate_lag(r.fused, r.vicon, options.max_lag_frames);
  }
}

}  // namespace

TrialAnalysis process_trial(const std::string& trial_name, const LmcRecording& recording, const Layout& layout,
                            const HandTrack* vicon, const ProcessOptions& options) {
  TrialAnalysis r;
  r.tag = parse_trial_tag(trial_name);
  r.method = options.method;
  r.layout_name = layout.name;
  r.input_kind = recording.kind;
  r.warnings = recording.warnings;

  refuse_length_correction_with_reference(options);
  if (recording.rows.empty()) throw Error("the LMC recording has no data rows");
  const auto ids = recording.device_ids();
  if (!ids.empty() && ids.back() > layout.device_count()) {
    throw Error("the recording has " + std::to_string(ids.size()) + " device(s) (highest id " +
                std::to_string(ids.back()) + ") but layout '" + layout.name + "' has only " +
                std::to_string(layout.device_count()));
  }
  if (vicon != nullptr) {
    const double seconds = vicon->frame_count / 100.0;
    if (seconds < options.min_vicon_seconds) {
      throw Error("the Vicon file has " + std::to_string(vicon->frame_count) + " frames (" +
                  std::to_string(seconds).substr(0, 4) + " s at 100 Hz), shorter than " +
                  std::to_string(options.min_vicon_seconds).substr(0, 3) + " s");
    }
  }

  // 1. Resample (raw) or take the study's resampled grid as it is.
  if (recording.kind == RecordingKind::kRaw) {
    r.device_frame = resample_recording(recording, options.resample, &r.resample);
    for (const auto& line : r.resample.summary_lines()) r.warnings.push_back(line);
  } else {
    r.device_frame = grid_from_resampled(recording, &r.warnings);
  }
  r.lmc_frames_before_trim = r.device_frame.frame_count;

  // Trim to the shorter series before fusion, as the study did (docs/algorithms/processing.md, stage 7).
  HandTrack vicon_trimmed;
  if (vicon != nullptr) {
    r.has_vicon = true;
    r.vicon_frames_before_trim = vicon->frame_count;
    vicon_trimmed = *vicon;
    if (options.trim_to_vicon) {
      const int limit = std::min(r.device_frame.frame_count, vicon->frame_count);
      trim_grid(r.device_frame, limit);
      vicon_trimmed.resize(limit);
    }
  }

  // 2. Visibility labels in each device's own frame.
  r.labels.resize(r.device_frame.devices.size());
  for (size_t d = 0; d < r.device_frame.devices.size(); ++d) {
    r.labels[d] = visibility_labels(r.device_frame.devices[d].track, options.visibility);
    r.visibility.push_back(visibility_table(r.device_frame.devices[d].device_id, r.labels[d]));
  }

  // 3. Realign.
  r.world = r.device_frame;
  realign_to_world(r.world, layout, layout.name);

  if (vicon != nullptr) r.vicon = std::move(vicon_trimmed);
  fuse_measure_compare(r, trial_name, options);
  return r;
}

TrialAnalysis process_trial_with_method(const TrialAnalysis& done, const std::string& trial_name,
                                        const ProcessOptions& options) {
  return process_trial_with_method(TrialAnalysis(done), trial_name, options);
}

TrialAnalysis process_trial_with_method(TrialAnalysis&& done, const std::string& trial_name,
                                        const ProcessOptions& options) {
  refuse_length_correction_with_reference(options);
  // Everything of steps 1–3 as it is; steps 4–6 overwrite what they compute.
  TrialAnalysis r = std::move(done);
  r.method = options.method;
  r.length_correction.reset();
  fuse_measure_compare(r, trial_name, options);
  return r;
}

}  // namespace lmc
