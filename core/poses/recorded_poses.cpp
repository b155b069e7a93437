#include "core/poses/recorded_poses.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>

#include "core/common/error.h"
#include "core/common/glob_match.h"
#include "core/hand/hand_track.h"
#include "core/hand/palm_axes.h"
#include "core/io/lmc_recording.h"
#include "core/io/vicon_mapping.h"
#include "core/processing/batch.h"
#include "core/processing/realign.h"
#include "core/processing/trial_tag.h"
#include "core/session/session_trials.h"

namespace lmc {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kFusedSuffix = ".fused.txt";

std::string pose_source_lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// One trial to read: the file the frames come from and, for a controller or Vicon source, how the
// processing pipeline found it (its layout, its Vicon file).
struct TrialInput {
  std::string trial;
  fs::path file;
  TrialSources job;
  bool process_now = false;  // fused source from a raw recording: processed here first
};

PoseLabel label_of_trial(const std::string& trial) {
  const TrialTag tag = parse_trial_tag(trial);
  PoseLabel label;
  label.orientation = tag.pose == "vertical" ? HandOrientation::kVertical : HandOrientation::kHorizontal;
  if (tag.motion == "index") label.motion = HandMotion::kIndexFlexion;
  if (tag.motion == "thumb") label.motion = HandMotion::kThumbFlexion;
  if (tag.motion == "wrist") label.motion = HandMotion::kWristFlexion;
  return label;
}

std::vector<TrialInput> recording_inputs(const fs::path& input, const RecordedPoseOptions& options,
                                         std::vector<std::string>& notes);

// Processed trials (`<trial>.fused.txt`) when the input holds them; otherwise the raw trials it
// holds, processed here (default fusion, as `lmc process` would) to get their fused hand.
std::vector<TrialInput> fused_inputs(const fs::path& input, const RecordedPoseOptions& options,
                                     std::vector<std::string>& notes) {
  std::vector<TrialInput> out;
  auto add = [&](const fs::path& file) {
    const std::string name = file.filename().string();
    out.push_back({name.substr(0, name.size() - kFusedSuffix.size()), file, {}, false});
  };
  if (!fs::exists(input)) throw Error(ErrorLocation(input.string()), "no such file or folder");
  if (fs::is_directory(input)) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(input)) {
      if (e.is_regular_file() && e.path().filename().string().ends_with(kFusedSuffix)) files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& f : files) add(f);
    if (!out.empty()) return out;
  } else if (input.filename().string().ends_with(kFusedSuffix)) {
    add(input);
    return out;
  }
  out = recording_inputs(input, options, notes);
  for (auto& t : out) t.process_now = true;
  return out;
}

std::vector<TrialInput> recording_inputs(const fs::path& input, const RecordedPoseOptions& options,
                                         std::vector<std::string>& notes) {
  std::vector<TrialInput> out;
  const std::string ext = pose_source_lower(input.extension().string());
  if (options.source == RecordedPoseSource::kVicon && fs::is_regular_file(input) && (ext == ".trc" || ext == ".c3d")) {
    TrialSources job;
    job.trial = trial_name_of(input.filename().string());
    job.vicon = input;
    out.push_back({job.trial, input, job, false});
    return out;
  }
  for (auto& job : trial_sources_for_input(input, std::nullopt, &notes)) {
    if (options.source == RecordedPoseSource::kVicon) {
      if (!job.vicon) {
        notes.push_back(job.lmc.string() + ": no Vicon file (" + job.trial + ".trc or .c3d) beside it; left out");
        continue;
      }
      out.push_back({job.trial, *job.vicon, job, false});
    } else {
      out.push_back({job.trial, job.lmc, job, false});
    }
  }
  return out;
}

struct TrialFrames {
  std::vector<HandFrame> frames;
  RecordedTrialCount count;
  std::string skipped;  // non-empty: the trial gave nothing, and why (naming the file)
};

// Keeps one frame when its 28 points are finite; fills missing palm axes from the points.
bool keep_frame(HandFrame& f, TrialFrames& out) {
  for (int i = 0; i < kNumHandPoints; ++i) {
    if (i == kPalmNormal || i == kPalmDirection) continue;
    if (!is_finite(f.point(i))) return false;
  }
  const bool axes_ok = is_finite(f.point(kPalmNormal)) && is_finite(f.point(kPalmDirection)) &&
                       f.point(kPalmNormal).norm() > 0.5 && f.point(kPalmDirection).norm() > 0.5;
  if (!axes_ok) {
    const PalmAxes axes = estimate_palm_axes(f);
    if (!is_finite(axes.normal)) return false;
    f.point(kPalmNormal) = axes.normal;
    f.point(kPalmDirection) = axes.direction;
    ++out.count.palm_axes_estimated;
  }
  f.hand_present = true;
  return true;
}

void take_rows(const std::vector<HandFrame>& rows, int every, TrialFrames& out,
               const std::function<bool(HandFrame&)>& to_world) {
  for (size_t i = 0; i < rows.size(); i += static_cast<size_t>(every)) {
    HandFrame f = rows[i];
    if (!f.hand_present || !to_world(f) || !keep_frame(f, out)) {
      ++out.count.frames_skipped;
      continue;
    }
    out.frames.push_back(f);
  }
}

TrialFrames read_trial(const TrialInput& in, const RecordedPoseOptions& options, const ViconMapping* mapping) {
  TrialFrames out;
  out.count.trial = in.trial;
  out.count.file = in.file.string();
  try {
    if (options.source == RecordedPoseSource::kFused && in.process_now) {
      BatchOptions batch;
      batch.layout = options.layout;
      const TrialAnalysis result = process_sources_in_full(in.job, batch);
      std::vector<HandFrame> rows(static_cast<size_t>(result.fused.frame_count));
      for (int k = 0; k < result.fused.frame_count; ++k) {
        HandFrame& f = rows[static_cast<size_t>(k)];
        f.frame_id = k;
        f.hand_present = result.fused.has_hand(k);
        for (int i = 0; i < kNumHandPoints; ++i) f.point(i) = result.fused.at(k, i);
      }
      take_rows(rows, options.every, out, [](HandFrame&) { return true; });
    } else if (options.source == RecordedPoseSource::kFused) {
      const LmcRecording rec = read_lmc_recording(in.file);
      take_rows(rec.rows, options.every, out, [](HandFrame&) { return true; });
    } else if (options.source == RecordedPoseSource::kController) {
      std::string used;
      Layout layout;
      try {
        layout = resolve_layout(in.job, options.layout, &used);
      } catch (const std::exception& e) {
        out.skipped = in.file.string() + ": no layout to bring LMC" + std::to_string(options.controller) +
                      " into the world frame (" + e.what() + ")";
        return out;
      }
      if (options.controller > static_cast<int>(layout.devices.size())) {
        out.skipped = in.file.string() + ": the trial's layout (" + used + ") has " +
                      std::to_string(layout.devices.size()) + " controllers, no LMC" +
                      std::to_string(options.controller);
        return out;
      }
      const LayoutDevice& device = layout.devices[static_cast<size_t>(options.controller - 1)];
      const Eigen::Matrix3d rotation = device.pose.rotation();
      const Eigen::Vector3d shift = device.pose.translation() + device.offset_mm;
      LmcRecording rec = read_lmc_recording(in.file);
      std::vector<HandFrame> rows;
      for (auto& r : rec.rows) {
        if (r.device_id == options.controller) rows.push_back(r);
      }
      if (rows.empty()) {
        out.skipped = in.file.string() + ": no rows of LMC" + std::to_string(options.controller);
        return out;
      }
      take_rows(rows, options.every, out, [&](HandFrame& f) {
        realign_frame(std::span<Vec3, kNumHandPoints>(f.points), rotation, shift);
        return true;
      });
    } else {
      const HandTrack track = apply_vicon_mapping(*mapping, load_vicon_markers(in.file));
      std::vector<HandFrame> rows(static_cast<size_t>(track.frame_count));
      for (int k = 0; k < track.frame_count; ++k) {
        HandFrame& f = rows[static_cast<size_t>(k)];
        f.frame_id = k;
        f.hand_present = true;
        for (int i = 0; i < kNumHandPoints; ++i) f.point(i) = track.at(k, i);
        // The mapping leaves the palm axes zero: estimated from the points in keep_frame.
        f.point(kPalmNormal) = f.point(kPalmDirection) = Vec3::Constant(std::nan(""));
      }
      take_rows(rows, options.every, out, [](HandFrame&) { return true; });
    }
  } catch (const std::exception& e) {
    out.frames.clear();
    out.skipped = e.what();
    return out;
  }
  out.count.frames_kept = static_cast<int>(out.frames.size());
  if (out.frames.empty()) {
    out.skipped = in.file.string() + ": no frame with a complete hand (" + std::to_string(out.count.frames_skipped) +
                  " frames read)";
  }
  return out;
}

std::string source_words(const RecordedPoseOptions& o) {
  switch (o.source) {
    case RecordedPoseSource::kFused:
      return "fused hand (world frame): lmc process output, or raw trials processed here with the default fusion";
    case RecordedPoseSource::kController:
      return "LMC" + std::to_string(o.controller) + " alone, realigned into the world frame with each trial's layout";
    case RecordedPoseSource::kVicon:
      return "Vicon markers mapped to the hand's points (skin markers as joints; palm axes estimated from the "
             "points)";
  }
  return {};
}

}  // namespace

void parse_recorded_pose_source(const std::string& text, RecordedPoseOptions& options) {
  const std::string t = pose_source_lower(text);
  if (t == "fused") {
    options.source = RecordedPoseSource::kFused;
    return;
  }
  if (t == "vicon") {
    options.source = RecordedPoseSource::kVicon;
    return;
  }
  if (t.size() == 4 && t.rfind("lmc", 0) == 0 && t[3] >= '1' && t[3] <= '8') {
    options.source = RecordedPoseSource::kController;
    options.controller = t[3] - '0';
    return;
  }
  throw Error(ErrorLocation("--source"), "unknown pose source \"" + text + "\" (fused, vicon or LMC1 … LMC8)");
}

std::string recorded_pose_source_name(const RecordedPoseOptions& options) {
  switch (options.source) {
    case RecordedPoseSource::kFused:
      return "fused";
    case RecordedPoseSource::kVicon:
      return "vicon";
    case RecordedPoseSource::kController:
      return "LMC" + std::to_string(options.controller);
  }
  return {};
}

namespace {

// The trials of every input that the --trials pattern keeps; throws, with the notes, when none.
std::vector<TrialInput> collect_pose_trials(const std::vector<fs::path>& inputs, const RecordedPoseOptions& options,
                                            std::vector<std::string>& notes) {
  std::vector<TrialInput> trials;
  for (const auto& input : inputs) {
    auto found = options.source == RecordedPoseSource::kFused ? fused_inputs(input, options, notes)
                                                              : recording_inputs(input, options, notes);
    for (auto& t : found) {
      if (!options.trials_glob.empty() && !glob_matches(options.trials_glob, t.trial)) continue;
      trials.push_back(std::move(t));
    }
  }
  if (trials.empty()) {
    std::string why = "no trials to read";
    if (!options.trials_glob.empty()) why += " match --trials \"" + options.trials_glob + "\"";
    for (const auto& n : notes) why += "\n  " + n;
    throw Error(ErrorLocation(inputs.front().string()), why);
  }
  return trials;
}

// The frames of the trials read (in the inputs' order), each labelled with its trial's pose;
// trials that gave nothing are listed as skipped.
void append_read_trials(std::vector<TrialFrames>& read, const std::vector<char>& done_flag, RecordedPoseSet& out) {
  size_t frames = 0;
  for (const auto& r : read) frames += r.frames.size();
  out.set.frames.reserve(frames);
  out.set.labels.reserve(frames);
  for (size_t i = 0; i < read.size(); ++i) {
    if (!done_flag[i]) continue;
    TrialFrames& r = read[i];
    if (!r.skipped.empty()) {
      out.skipped.push_back(r.skipped);
      continue;
    }
    const PoseLabel label = label_of_trial(r.count.trial);
    for (auto& f : r.frames) {
      f.frame_id = static_cast<std::int64_t>(out.set.frames.size());
      out.set.frames.push_back(f);
      out.set.labels.push_back(label);
    }
    out.frames_skipped += r.count.frames_skipped;
    out.trials.push_back(r.count);
  }
}

// The set's description and provenance lines: source, inputs, trials, frames, what was left out.
void describe_recorded_pose_set(RecordedPoseSet& out, const std::vector<fs::path>& inputs,
                                const RecordedPoseOptions& options, int processed_now) {
  // Many inputs (the Review tab passes each trial's file): the first and a count.
  std::string where = inputs.front().string();
  if (inputs.size() == 2) where += ", " + inputs[1].string();
  if (inputs.size() > 2) where += " and " + std::to_string(inputs.size() - 1) + " more";
  out.set.description = "recorded " + recorded_pose_source_name(options) + " from " + where + " (" +
                        std::to_string(out.trials.size()) + " trials, " + std::to_string(out.set.size()) + " frames" +
                        (options.every > 1 ? ", every " + std::to_string(options.every) + "th" : "") + ")";
  out.set.provenance.push_back(
      "source: " + source_words(options) +
      (processed_now > 0 ? " (" + std::to_string(processed_now) + " trials processed here)" : ""));
  out.set.provenance.push_back("inputs: " + where +
                               (options.trials_glob.empty() ? "" : " (trials " + options.trials_glob + ")"));
  std::string names;
  int estimated = 0;
  for (const auto& t : out.trials) {
    names += (names.empty() ? "" : ", ") + t.trial + " (" + std::to_string(t.frames_kept) + ")";
    estimated += t.palm_axes_estimated;
  }
  out.set.provenance.push_back("trials: " + names);
  out.set.provenance.push_back(
      "frames: " + std::to_string(out.set.size()) + " kept, " + std::to_string(out.frames_skipped) +
      " skipped (no complete hand)" +
      (options.every > 1 ? ", every " + std::to_string(options.every) + "th frame read" : "") +
      (estimated > 0 ? ", palm axes estimated from the points in " + std::to_string(estimated) : ""));
  if (!out.skipped.empty())
    out.set.provenance.push_back("trials left out: " + std::to_string(out.skipped.size()) +
                                 " (see the command's messages)");
}

}  // namespace

RecordedPoseSet pose_set_from_recordings(const std::vector<fs::path>& inputs, const RecordedPoseOptions& options,
                                         std::stop_token stop, const std::function<void(int, int)>& on_progress) {
  if (inputs.empty()) throw Error("no recordings given");
  if (options.every < 1) throw Error(ErrorLocation("--every"), "must be 1 or more");
  std::vector<std::string> notes;
  const std::vector<TrialInput> trials = collect_pose_trials(inputs, options, notes);
  std::optional<ViconMapping> mapping;
  if (options.source == RecordedPoseSource::kVicon)
    mapping = options.mapping ? load_vicon_mapping(*options.mapping) : default_vicon_mapping();

  std::vector<TrialFrames> read(trials.size());
  std::vector<char> done_flag(trials.size(), 0);
  std::atomic<int> done{0};
  const int total = static_cast<int>(trials.size());
  tbb::parallel_for(size_t{0}, trials.size(), [&](size_t i) {
    if (stop.stop_requested()) return;
    read[i] = read_trial(trials[i], options, mapping ? &*mapping : nullptr);
    done_flag[i] = 1;
    const int d = ++done;
    if (on_progress) on_progress(d, total);
  });

  RecordedPoseSet out;
  out.skipped = notes;
  int processed_now = 0;
  for (size_t i = 0; i < trials.size(); ++i)
    processed_now += done_flag[i] && trials[i].process_now && read[i].skipped.empty();
  out.cancelled = stop.stop_requested();
  append_read_trials(read, done_flag, out);
  if (out.set.frames.empty() && !out.cancelled) {
    std::string why = "no trial gave a frame with a complete hand:";
    for (const auto& s : out.skipped) why += "\n  " + s;
    throw Error(ErrorLocation(inputs.front().string()), why);
  }
  describe_recorded_pose_set(out, inputs, options, processed_now);
  return out;
}

}  // namespace lmc
