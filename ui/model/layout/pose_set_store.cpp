#include "ui/model/layout/pose_set_store.h"

#include <chrono>
#include <thread>

#include "core/hand/hand_model.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/pose_set_tsv.h"

namespace lmc::ui {

PoseSetPtr load_pose_set_for(const PoseSetChoice& choice, std::uint64_t version, std::stop_token stop) {
  auto out = std::make_shared<LoadedPoseSet>();
  out->version = version;
  out->choice = choice;
  if (choice.source == PoseSetChoice::Source::kFile) {
    out->set = load_pose_set(choice.file);
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
    ch.set_stage(choice.source == PoseSetChoice::Source::kFile ? "Reading pose set" : "Generating pose set");
    return load_pose_set_for(choice, version, stop);
  });
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
