#include "ui/model/layout/pose_set_store.h"

#include <chrono>
#include <thread>

#include "core/hand/hand_model.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/pose_set_tsv.h"
#include "core/poses/pose_recipe.h"
#include "core/poses/recorded_poses.h"

namespace lmc::ui {

PoseSetPtr load_pose_set_for(const PoseSetChoice& choice, std::uint64_t version, std::stop_token stop,
                             const std::function<void(int, int)>& on_progress) {
  auto out = std::make_shared<LoadedPoseSet>();
  out->version = version;
  out->choice = choice;
  if (choice.source == PoseSetChoice::Source::kFile) {
    // A pose-set file, or a recipe mixing recordings and the Monte Carlo set.
    out->set = load_pose_spec(choice.file, choice.frames, choice.seed, std::nullopt, &out->left_out);
  } else if (choice.source == PoseSetChoice::Source::kRecordings) {
    RecordedPoseOptions options;
    parse_recorded_pose_source(choice.recorded_source, options);
    options.trials_glob = choice.trials_glob;
    options.every = choice.every;
    const std::vector<std::filesystem::path> inputs(choice.recordings.begin(), choice.recordings.end());
    RecordedPoseSet rec = pose_set_from_recordings(inputs, options, stop, on_progress);
    if (rec.cancelled) return nullptr;
    out->set = std::move(rec.set);
    out->left_out = std::move(rec.skipped);
  } else {
    PoseSetSettings s;
    s.frames = choice.frames;
    s.seed = choice.seed;
    out->set = generate_pose_set(HandModel(), s);
  }
  // A newer request replaced this one: the frames are not prepared for nobody.
  if (stop.stop_requested()) return nullptr;
  out->prepared = prepare_frames(out->set.frames);
  out->horizontal = out->set.indices_with(HandOrientation::kHorizontal);
  out->vertical = out->set.indices_with(HandOrientation::kVertical);
  return out;
}

void PoseSetStore::request(const PoseSetChoice& choice) {
  if (has_request_ && requested_ == choice) return;
  requested_ = choice;
  has_request_ = true;
  error_.clear();
  const std::uint64_t version = next_version_++;
  job_.abandon_into(graveyard_);
  job_.start([choice, version](std::stop_token stop, JobChannel<int>& ch) {
    const char* stage = choice.source == PoseSetChoice::Source::kFile         ? "Reading pose set"
                        : choice.source == PoseSetChoice::Source::kRecordings ? "Reading recorded trials"
                                                                              : "Generating pose set";
    ch.set_stage(stage);
    return load_pose_set_for(choice, version, stop, [&ch](int done, int total) { ch.set_progress(done, total); });
  });
}

void PoseSetStore::cancel() {
  if (!job_.running()) return;
  job_.abandon_into(graveyard_);
  // The choice that was loading is forgotten, so asking for it again starts it again.
  has_request_ = current_ != nullptr;
  if (current_) requested_ = current_->choice;
  error_ = "Loading the pose set was cancelled; the set shown is the one loaded before.";
}

void PoseSetStore::poll() {
  graveyard_.reap();
  const JobState s = job_.state();
  if (s == JobState::kCompleted) {
    if (auto r = job_.result(); r && *r && (!current_ || (*r)->version != current_->version)) current_ = *r;
  } else if (s == JobState::kFailed) {
    error_ = job_.error();
  }
}

void PoseSetStore::wait() {
  while (job_.running()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  poll();
}

}  // namespace lmc::ui
