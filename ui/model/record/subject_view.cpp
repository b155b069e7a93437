#include "ui/model/record/subject_view.h"

#include <algorithm>
#include <cmath>

#include "ui/model/record/record_state.h"

namespace lmc::ui {

SubjectViewInputs subject_view_inputs(const RecordState& model) {
  SubjectViewInputs in;
  in.has_session = model.has_session();
  if (!in.has_session) return in;
  in.finished = model.finished();
  const auto& st = model.state();
  in.hand_length_mm = st.subject().hand_length_mm.value_or(0.0);
  in.hand_breadth_mm = st.subject().hand_breadth_mm.value_or(0.0);
  const int i = model.recording() ? model.recording_trial() : model.current_trial();
  if (i >= 0) {
    const auto& plan = st.trials.at(static_cast<size_t>(i)).plan;
    in.type = &model.trial_type(i);
    in.pose = &st.protocol.poses.at(static_cast<size_t>(plan.pose));
    in.sim_motion = plan.sim_motion;
  }
  if (model.recording()) {
    // Until the worker's first snapshot the trial is starting: the subject waits.
    in.phase = model.live() ? model.live()->phase : devices::TrialPhase::kWaitingForStreams;
    if (model.live()) {
      in.countdown_remaining_s = model.live()->countdown_remaining_s;
      in.recording_s = model.live()->recording_s;
    }
  }
  return in;
}

int countdown_number(double remaining_s) {
  return std::max(1, static_cast<int>(std::ceil(remaining_s - 1e-9)));
}

int seconds_left(double duration_s, double recording_s) {
  return static_cast<int>(std::ceil(std::max(0.0, duration_s - recording_s) - 1e-9));
}

SubjectView build_subject_view(const SubjectViewInputs& in, double t_s) {
  SubjectView v;
  if (!in.has_session) {
    // The subject may already sit in front of it: words for them, not for the operator.
    v.headline = "Welcome";
    v.cue = "Please make yourself comfortable. We will begin in a moment.";
    return v;
  }
  if (in.finished || in.type == nullptr) {
    v.stage = SubjectStage::kDone;
    v.headline = "Thank you";
    v.cue = "The session is complete.";
    return v;
  }
  v.cue = in.type->subject_cue;
  if (in.pose != nullptr) v.pose_cue = in.pose->cue;
  v.pictogram = motion_pictogram(in.sim_motion, t_s, in.hand_length_mm, in.hand_breadth_mm);
  if (!in.phase) {
    v.stage = SubjectStage::kGetReady;
    v.headline = "Get ready";
    return v;
  }
  switch (*in.phase) {
    case devices::TrialPhase::kCountdown: {
      v.stage = SubjectStage::kCountdown;
      v.headline = std::to_string(countdown_number(in.countdown_remaining_s));  // "3, 2, 1"
      break;
    }
    case devices::TrialPhase::kRecording:
    case devices::TrialPhase::kFinishing: {
      v.stage = SubjectStage::kRecording;
      v.red_circle = true;
      v.headline = "Recording";
      v.time_text = std::to_string(seconds_left(in.type->duration_s, in.recording_s)) + " s left";
      break;
    }
    case devices::TrialPhase::kDone:
      v.stage = SubjectStage::kGetReady;
      v.headline = "Get ready";
      break;
    default:  // waiting for the controllers or for Vicon
      v.stage = SubjectStage::kWaiting;
      v.headline = "Please wait";
      break;
  }
  return v;
}

}  // namespace lmc::ui
