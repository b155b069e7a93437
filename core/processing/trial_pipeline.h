#pragma once
// One trial through every stage (docs/algorithms/processing.md): resample → visibility labels (device
// frame) → realign → fuse → measures → compare with Vicon. Each stage is its own unit
// (resample.h, realign.h, visibility_labels.h, kalman_reference.h / fusion_smoother.h, measures.h,
// compare.h); this file only strings them together and keeps the intermediates so the workbench
// can show any of them.
#include <optional>
#include <string>
#include <vector>

#include "core/io/lmc_recording.h"
#include "core/layout/layout.h"
#include "core/processing/compare.h"
#include "core/processing/fusion_smoother.h"
#include "core/processing/kalman_reference.h"
#include "core/processing/length_correction.h"
#include "core/processing/measures.h"
#include "core/processing/resample.h"
#include "core/processing/trial_tag.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

enum class FusionMethod { kReference, kDefault };
const char* fusion_method_name(FusionMethod m);                 // "reference", "default"
FusionMethod fusion_method_from_name(const std::string& name);  // throws lmc::Error

struct ProcessOptions {
  FusionMethod method = FusionMethod::kDefault;
  ResampleOptions resample;
  ReferenceKalmanParams kalman;
  SmootherParams smoother;
  VisibilityParams visibility{400.0, 150.0, 120.0, 10.0};  // recorded-trial analysis (docs/algorithms/visibility.md)
  bool trim_to_vicon =
      true;  // as the study: both series cut to the shorter before fusion (docs/algorithms/processing.md, stage 7)
  int max_lag_frames = 50;
  double min_vicon_seconds = 1.0;  // a shorter Vicon file is rejected
  // Per-subject finger-length correction applied after fusion (length_correction.h). Off unless
  // given; with the reference method process_trial refuses it.
  std::optional<LengthCorrection> length_correction;
};

// Everything processing computed for one trial: every intermediate (the grid, the world tracks, the
// labels, the fused hand) and the measures, kept for the trial view, the exports and the reruns.
struct TrialAnalysis {
  TrialTag tag;
  std::string lmc_source, vicon_source;
  FusionMethod method = FusionMethod::kDefault;
  std::string layout_name;
  std::string layout_source;  // where the layout came from (preset, file, recorder sidecar)
  RecordingKind input_kind = RecordingKind::kRaw;
  std::vector<std::string> warnings;  // survivable problems, for the per-trial report
  ResampleReport resample;

  // Intermediates.
  GridTrial device_frame;                             // after resampling (and trimming)
  GridTrial world;                                    // after realignment
  std::vector<std::vector<FingerLabels>> labels;      // [device][frame]
  HandTrack fused;                                    // after the length correction, when one was given
  std::optional<LengthCorrection> length_correction;  // the one applied

  // Measures.
  std::vector<FrameMeasures> lmc_frames;
  MeasureStats lmc_stats;
  std::vector<VisibilityCounts> visibility;  // one per device

  bool has_vicon = false;
  HandTrack vicon;
  std::vector<FrameMeasures> vicon_frames;
  MeasureStats vicon_stats;
  Comparison comparison;
  int lmc_frames_before_trim = 0, vicon_frames_before_trim = 0;
};

// In memory. `vicon` (already mapped to the 30 points, 100 Hz) may be null. Throws lmc::Error
// for problems that stop this trial (no hand at all, layout with too few devices, Vicon too short,
// a length correction with the reference method).
TrialAnalysis process_trial(const std::string& trial_name, const LmcRecording& recording, const Layout& layout,
                            const HandTrack* vicon, const ProcessOptions& options);

// The same trial fused by another method: `done` came from process_trial with options that differ
// from `options` in the fusion method only, so its resampled grid, visibility labels, world tracks
// and trimmed Vicon are reused and only fusion, measures and comparison run again (a method
// comparison otherwise resamples and ray-traces every trial twice). Same result as process_trial.
TrialAnalysis process_trial_with_method(const TrialAnalysis& done, const std::string& trial_name,
                                        const ProcessOptions& options);
// The same, taking `done` over instead of copying it (its grids and tracks are megabytes a trial).
TrialAnalysis process_trial_with_method(TrialAnalysis&& done, const std::string& trial_name,
                                        const ProcessOptions& options);

}  // namespace lmc
