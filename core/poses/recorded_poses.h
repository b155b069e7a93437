#pragma once
// Pose sets from recordings: the hands a lab's own subjects made, each frame in the world frame as
// the visibility kernel takes it (docs/algorithms/metric.md), so a layout can be designed and judged
// on what the task really produces instead of on an invented Monte Carlo set.
//
// Three sources of a frame's hand:
//  * fused (default): the fused hand `lmc process` writes (`<trial>.fused.txt`, world frame); raw
//    trials (a session, a folder, an LMC file) are processed here first with the default fusion,
//    exactly as `lmc process` would (process_sources_in_full), and their fused hand is taken;
//  * one controller (LMCn): that controller's rows of the recording, realigned into the world frame
//    with the trial's layout (realign_frame: pose and offset), every tracking event it sent;
//  * vicon: the trial's Vicon markers mapped to the 30 points (core/io/vicon_mapping.h: palm = Hand4,
//    elbow = Forearm1, wrist = mean of Forearm2/3, knuckles and finger joints from skin markers, the
//    middle and ring metacarpal bases interpolated between Hand3 and Hand1). Joint centres are thus
//    skin-marker positions, not estimated joint centres; the markers are taken to be in the world
//    frame (the simulator writes them so; a lab's Vicon origin must be the table centre, y up).
// Palm normal and direction: the kernel does not use them; a frame without finite ones (every Vicon
// frame) gets them from estimate_palm_axes (core/hand/palm_axes.h), counted as estimated.
//
// A frame is kept when its 28 points are finite; others are skipped and counted per trial. A trial
// that gives no frame (no hand, no such controller, no layout for a controller source, no Vicon
// file, a file that cannot be read) is skipped with a message naming the file; when no trial gives a
// frame the build throws lmc::Error with those messages. Each frame's label comes from the trial's
// name (core/processing/trial_tag.h: pose → orientation, motion → motion; static and unknown → open
// hand), progress 0.
//
// Trials are read in parallel (oneTBB); the set is the trials' frames in input order, whatever the
// thread count.
#include <filesystem>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/hand/pose_set.h"

namespace lmc {

enum class RecordedPoseSource { kFused, kVicon, kController };

struct RecordedPoseOptions {
  RecordedPoseSource source = RecordedPoseSource::kFused;
  int controller = 0;                            // kController: 1-based device id (LMC1 = 1)
  int every = 1;                                 // keep every N-th frame of each trial (N ≥ 1)
  std::string trials_glob;                       // shell pattern on the trial name ("*Index*"); empty = every trial
  std::optional<std::string> layout;             // kController, raw trials for kFused: overrides the trial's own layout
  std::optional<std::filesystem::path> mapping;  // kVicon: another marker mapping
};

// "fused", "vicon", "LMC1" … "LMC8" (case-insensitive "lmc"); throws lmc::Error naming the text.
void parse_recorded_pose_source(const std::string& text, RecordedPoseOptions& options);
std::string recorded_pose_source_name(const RecordedPoseOptions& options);

struct RecordedTrialCount {
  std::string trial;
  std::string file;
  int frames_kept = 0;
  int frames_skipped = 0;       // no complete hand (a hand missing or a point not finite)
  int palm_axes_estimated = 0;  // kept frames whose palm normal/direction came from the points
};

struct RecordedPoseSet {
  PoseSet set;
  std::vector<RecordedTrialCount> trials;  // the trials that gave frames, in input order
  std::vector<std::string> skipped;        // one message per trial left out, naming its file
  int frames_skipped = 0;                  // over the trials that gave frames
  bool cancelled = false;
};

// `inputs`: processed-trial folders or `.fused.txt` files, or raw ones (fused); session or trial
// folders, LMC files (controller, vicon) or Vicon files (`.trc`, `.c3d`; vicon). `on_progress(done, total)` is
// called after each trial (from worker threads). Once `stop` is requested, trials not yet read are
// left out and `cancelled` is set.
RecordedPoseSet pose_set_from_recordings(const std::vector<std::filesystem::path>& inputs,
                                         const RecordedPoseOptions& options, std::stop_token stop = {},
                                         const std::function<void(int done, int total)>& on_progress = {});

}  // namespace lmc
