#pragma once
// A processed trial as one table of labelled 3-D points for motion-analysis tools (C3D, TRC), one
// implementation for `lmc export` and the Review tab (docs/export.md):
//   F_<landmark>        the fused hand
//   LMC<n>_<landmark>   controller n's own hand, realigned into the world frame (LMC1 = 1)
//   V_<marker>          the trial's Vicon markers as the Vicon file names them (characters other than
//                       letters, digits, '_' and '-' become '_'), when the trial has a Vicon file
// Landmarks, 28 per hand: Palm, Elbow, Wrist, then <Digit>_<Joint> with Digit Thumb, Index, Middle,
// Ring, Pinky and Joint Meta, Proxi (the MCP joint), Inter, Dist, End (the study's naming; the
// thumb's Meta coincides with its Proxi). The palm normal and direction are directions, not points,
// and are left out. Every series is on the processing grid (100 Hz, frame f at f / 100 s from the
// trial's first frame); Vicon frame f is grid frame f, as processing and the Review tab align them.
// Units mm. A point without data in a frame (no hand, Vicon gap) is NaN, never 0.
// Axes: the world frame (docs/algorithms/frames.md: x along the table, y up, z towards the subject)
// or OpenSim's convention (X forward from the subject = −z, Y up = y, Z to the subject's right = x).
#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/io/c3d.h"
#include "core/io/trc.h"
#include "core/io/vicon_mapping.h"
#include "core/processing/batch.h"
#include "core/processing/trial_pipeline.h"

namespace lmc {

enum class ExportAxes { kWorld, kOpenSim };
const char* export_axes_name(ExportAxes axes);              // "world", "opensim"
ExportAxes export_axes_from_name(const std::string& name);  // throws lmc::Error
// In words, for a file's description and the --help text.
std::string export_axes_words(ExportAxes axes);

// The 28 hand points exported per hand, in file order (indices into HandTrack points).
const std::vector<int>& exported_hand_points();
// "Palm", "Elbow", "Wrist", "Index_Dist", …; empty for a point that is not exported.
std::string landmark_name(int hand_point);
// A label usable in either format: letters, digits, '_' and '-' kept, anything else '_'.
std::string export_label(const std::string& name);

struct PointTable {
  std::string trial;
  double rate_hz = 100.0;
  ExportAxes axes = ExportAxes::kWorld;
  std::vector<std::string> labels;
  std::vector<std::string> descriptions;                // one per label, for C3D POINT:DESCRIPTIONS
  std::vector<std::vector<Eigen::Vector3d>> positions;  // [frame][point], mm, NaN = missing
  bool has_vicon = false;
  int frame_count() const { return static_cast<int>(positions.size()); }
  int point_count() const { return static_cast<int>(labels.size()); }
  int label_index(const std::string& label) const;  // −1 when absent
};

// `vicon_markers` (optional) are the trial's Vicon markers as read from its file (mm).
PointTable trial_point_table(const TrialAnalysis& result, const MarkerSeries* vicon_markers, ExportAxes axes);

C3dData point_table_c3d(const PointTable& table);
TrcData point_table_trc(const PointTable& table);

enum class ExportFormat { kC3d, kTrc };
const char* export_format_extension(ExportFormat format);  // ".c3d", ".trc"

struct TrialExportRequest {
  std::vector<std::filesystem::path> inputs;  // recordings, processed trials or session folders
  std::filesystem::path out_dir;
  ExportFormat format = ExportFormat::kC3d;
  ExportAxes axes = ExportAxes::kWorld;
  bool force = false;  // replace files that exist
  BatchOptions session;
  // Called once per trial as it is written or left out, for a command's progress lines.
  std::function<void(const std::string& line)> on_trial;
  // Called before each trial and once at the end: trials done, trials planned (a progress bar).
  std::function<void(int done, int total)> on_progress;
  // Polled before each trial: true stops the export there. Files already written stay (each is
  // complete: they are written atomically); the report says cancelled.
  std::function<bool()> should_stop;
};

struct TrialExportReport {
  std::vector<std::filesystem::path> written;
  std::vector<std::string> exported;  // trial names
  std::vector<std::string> notes;     // what was left out or is partial, and why
  int left_out = 0;                   // trials (or inputs) not exported
  bool cancelled = false;             // should_stop ended it before every trial was done
};

// Every trial of every input to <out_dir>/<trial>.c3d|.trc. Trials whose file name would not be a
// safe name, repeated trial names and trials that fail processing are left out with a note; the
// others are written. Files that exist are refused before anything is written unless `force`.
// Nothing is written outside `out_dir`. Throws lmc::Error when no trial could be found at all or
// an output exists without `force`.
TrialExportReport export_trials(const TrialExportRequest& request);

}  // namespace lmc
